#pragma once

#include "frontend/frontend.h"

namespace ncc::nc110 {

[[nodiscard]] std::unique_ptr<Frontend> make_nc110_frontend(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::nc110
