// Text made to fit a width in the built-in font (image.h), so that no label
// is cut at a picture's edge: items are flowed into lines and broken only
// between items; an item wider than a line is shortened to end in "..";
// items that do not fit in the lines allowed are counted in "+N more".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace afford::render {

// The text if it fits in `width` px at `scale`, else its longest start that
// fits with ".." after it ("" when not even ".." fits).
std::string fit_text(std::string_view text, int width, int scale);

// Groups of items into lines of at most `width` px: each group starts a
// line, items of a group are joined by `sep` while they fit. At most
// `max_lines` lines (0: no limit); when items are left over, the last line
// ends in "+N more" (its own items dropped from the end until that fits).
std::vector<std::string> flow(const std::vector<std::vector<std::string>>& groups, int width, int scale,
                              std::string_view sep, size_t max_lines = 0);

}  // namespace afford::render
