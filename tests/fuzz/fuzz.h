// What the fuzz targets share (docs/limits.md, "Fuzzing"). Each target defines
// LLVMFuzzerTestOneInput. Built with -DNCC_LIBFUZZER=ON (Clang), libFuzzer drives it;
// otherwise replay() is its main and runs the inputs it is given once each, so that
// the crashes found (tests/fuzz/regressions/) run in every build's test suite. A
// target runs ncc in-process and prints nothing unless an invariant breaks.
#pragma once

#include <cstdint>

#include "driver/pipeline.h"

namespace ncc::fuzz {

// Prepares a fresh session as ncc does for a source program: the built-in machine
// profile (parsed once, then shared: parsing it anew took a quarter of each input's
// time), no program library (an input may call any program it names; calls find
// nothing).
void start_session(Session& s);

// How every dry run and run goes: at most 2,000 steps (a program that loops forever,
// or a cycle repeated 10^6 times, costs little), no ASSET sandbox, no input script.
RunSettings run_settings();

// Writes the module and reads it back: it must load (verified) and disassemble to the
// same text, else the target aborts.
void round_trip(const vm::Module& m);

// Runs the module as `ncc run` does, with a null trace.
void run(Session& s, const vm::Module& m);

// Formats the session's diagnostics as text, JSON and SARIF (and throws them away).
void format_diagnostics(const Session& s);

// Aborts with a message on stderr: a property every input must keep did not hold.
[[noreturn]] void fail(const std::string& what);

// The replay driver: runs every file given, and every file under every directory
// given (in name order), once. Arguments beginning with '-' are libFuzzer's options
// and are ignored, so that one command line serves both builds.
int replay(int argc, char** argv);

}  // namespace ncc::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
