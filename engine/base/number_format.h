// Numbers as printf writes them ("%.*f", "%.*g"), byte for byte, without a
// format string parsed and the locale consulted, and mostly without the
// exact (and slow) decimal conversion: a trace writes seven of them a frame.
//
// The common case takes one multiplication or division by an exact power of
// ten and one rounding to an integer. That rounding can only go the other
// way than the exact value's when the scaled value lies close to a tie
// (n + 0.5); there, and for precisions above 9, very large or very small
// magnitudes, inf and nan, std::to_chars (exact, printf's rounding) writes
// the number instead.
#pragma once

namespace afford {

// printf's "%.{precision}f" of v into [p, end); returns the end of the text
// (no terminating NUL). [p, end) must hold what printf would write.
char* write_fixed(char* p, char* end, double v, int precision);

// printf's "%.{precision}g" of v into [p, end); returns the end of the text.
char* write_general(char* p, char* end, double v, int precision);

}  // namespace afford
