#include "text_fit.h"

#include "image.h"

namespace afford::render {

std::string fit_text(std::string_view text, int width, int scale) {
  if (text_width(text, scale) <= width) return std::string(text);
  for (size_t n = text.size(); n-- > 0;) {
    const std::string s = std::string(text.substr(0, n)) + "..";
    if (text_width(s, scale) <= width) return s;
  }
  return "";
}

std::vector<std::string> flow(const std::vector<std::vector<std::string>>& groups, int width, int scale,
                              std::string_view sep, size_t max_lines) {
  // Every line as its items, so that the last can give some up for "+N more".
  std::vector<std::vector<std::string>> lines;
  for (const std::vector<std::string>& group : groups) {
    bool fresh = true;  // a group starts a line
    std::string joined;
    for (const std::string& item : group) {
      const std::string one = fit_text(item, width, scale);
      if (!fresh && text_width(joined + std::string(sep) + one, scale) <= width) {
        lines.back().push_back(one);
        joined += std::string(sep) + one;
        continue;
      }
      lines.push_back({one});
      joined = one;
      fresh = false;
    }
  }
  size_t left_over = 0;
  if (max_lines > 0 && lines.size() > max_lines) {
    for (size_t i = max_lines; i < lines.size(); ++i) left_over += lines[i].size();
    lines.resize(max_lines);
  }
  auto join = [&sep](const std::vector<std::string>& items) {
    std::string s;
    for (size_t i = 0; i < items.size(); ++i) s += (i ? std::string(sep) : std::string()) + items[i];
    return s;
  };
  std::vector<std::string> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i + 1 < lines.size() || left_over == 0) {
      out.push_back(join(lines[i]));
      continue;
    }
    std::vector<std::string>& last = lines[i];
    for (;;) {
      const std::string more = "+" + std::to_string(left_over) + " more";
      const std::string s = last.empty() ? more : join(last) + std::string(sep) + more;
      if (text_width(s, scale) <= width || last.empty()) {
        out.push_back(fit_text(s, width, scale));
        break;
      }
      last.pop_back();
      ++left_over;
    }
  }
  return out;
}

}  // namespace afford::render
