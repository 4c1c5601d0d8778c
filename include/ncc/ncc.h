// ncc: compile part programs of the gost, nc110, pp and iso dialects, and run them on
// a machine of your own. Start with docs/architecture.md and examples/embed/.
#pragma once

#include "diagnostic.h"
#include "machine_interface.h"
#include "program.h"
#include "run.h"
