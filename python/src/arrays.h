// NumPy arrays that take over a std::vector's storage: no copy, the array
// frees the vector when Python drops it.
#pragma once

#include <pybind11/numpy.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace afford::python {

template <typename T>
pybind11::array_t<T> as_array(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>({static_cast<pybind11::ssize_t>(owned->size())}, {static_cast<pybind11::ssize_t>(sizeof(T))},
                              owned->data(), free_it);
}

// 0/1 bytes as a NumPy bool array, no copy (std::vector<bool> packs bits).
inline pybind11::array as_bool_array(std::vector<std::uint8_t>&& values) {
  auto* owned = new std::vector<std::uint8_t>(std::move(values));
  pybind11::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
  return pybind11::array(pybind11::dtype::of<bool>(), {static_cast<pybind11::ssize_t>(owned->size())}, {pybind11::ssize_t{1}},
                         owned->data(), free_it);
}

}  // namespace afford::python
