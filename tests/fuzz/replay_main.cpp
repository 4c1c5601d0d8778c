// The main of a fuzz target built without libFuzzer (fuzz.h).
#include "fuzz.h"

int main(int argc, char** argv) { return ncc::fuzz::replay(argc, argv); }
