#pragma once

#include "frontend/frontend.h"

namespace ncc::pp {

[[nodiscard]] std::unique_ptr<Frontend> make_pp_frontend(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::pp
