// Writing a whole buffer to a file descriptor: the one loop that retries
// short writes and EINTR, shared by the output files and the recorder.
#pragma once

#include <cstddef>

namespace afford {

// Writes all n bytes at p to fd. Returns 0, or the errno of the failed write.
int write_all(int fd, const void* p, size_t n);

}  // namespace afford
