// What the ncc library exports: the classes and functions of include/ncc/ and
// nothing else (the library is built with hidden visibility).
#pragma once

#if defined(NCC_STATIC)
#define NCC_API
#else
#define NCC_API __attribute__((visibility("default")))
#endif
