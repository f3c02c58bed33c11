/// @file allocation_counter.cpp
/// @brief The counting operator new of the sync suite, in a unit of its own (frame_side_test reads the counters).
#include "../../sim/allocation_counter.h"
