// Counts every heap allocation in the process (operator new is replaced in
// alloc_counter.cpp), so a benchmark can show a frame allocates nothing.
#pragma once

long allocation_count();
