// The control for backward.cpp: the same library set-up, including its own layer and one below it,
// compiles (CTest "validation: a downward include builds"). Built only by that test.
#include "common/output.hpp"
#include "inputs/cases.hpp"
