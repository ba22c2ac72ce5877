// The column helpers of the batched orbit bindings (py_batch.cpp,
// py_system_batch.cpp): names and values checked under the GIL, results moved
// into read-only NumPy arrays without a copy.
#pragma once

#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::python {

inline std::string TypeName(const py::handle& x) {
  return py::str(py::type::of(x).attr("__name__")).cast<std::string>();
}

// A read-only array that owns v's buffer (no copy).
template <typename T>
py::array Owned(std::vector<T>&& v) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  py::array_t<T> a(static_cast<py::ssize_t>(heap->size()), heap->data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

// One column: a str key naming a parameter (ValueError if it is none) and a
// 1-D sequence of real numbers (TypeError for other types, ValueError for
// another shape).
inline std::vector<double> Values(const std::string& name, const py::handle& values) {
  const py::array a = py::module_::import("numpy").attr("asarray")(values);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("orbits: column '" + name + "' must hold real numbers, not " +
                         (py::isinstance<py::array>(values)
                              ? "an array of dtype " + py::str(a.dtype()).cast<std::string>()
                              : TypeName(values)));
  if (a.ndim() != 1)
    throw InvalidArgument("orbits: column '" + name + "' must be 1-D, not of shape " +
                          py::str(a.attr("shape")).cast<std::string>());
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<double>(d.data(), d.data() + d.size());
}

inline std::string KeyOf(const py::handle& key) {
  if (!py::isinstance<py::str>(key))
    throw py::type_error("orbits: column names must be parameter names (str), not " +
                         TypeName(key));
  return key.cast<std::string>();
}

}  // namespace stickslip::python
