// Counts every heap allocation in the process (operator new is replaced in
// alloc_counter.cpp), so a benchmark or a test can show a frame allocates
// nothing: in the whole process, or on the calling thread only (the frame
// thread of afford serve, while other threads allocate freely).
#pragma once

long allocation_count();         // operator new calls in the process
long thread_allocation_count();  // operator new calls on the calling thread
