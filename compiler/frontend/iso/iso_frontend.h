#pragma once

#include "frontend/frontend.h"

namespace ncc::iso {

[[nodiscard]] std::unique_ptr<Frontend> make_iso_frontend(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::iso
