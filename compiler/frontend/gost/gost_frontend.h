#pragma once

#include "frontend/frontend.h"

namespace ncc::gost {

[[nodiscard]] std::unique_ptr<Frontend> make_gost_frontend(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::gost
