#pragma once

#include "frontend/frontend.h"

namespace ncc::linuxcnc {

std::unique_ptr<Frontend> make_linuxcnc_frontend(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::linuxcnc
