// libFuzzer target: read_mesh on arbitrary bytes as a .stl file.
#include "fuzz_read_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return fuzz_read_mesh(data, size, "stl"); }
