// stickslip.System: a friction system of the user's own, from a model file
// or its text (docs/model_files.md), in every function that takes a system
// (SystemOf: simulate, system_orbit, continue_orbits, steady_sliding, chart,
// attractor_basins, ...). Its parameters are read and set by name.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "model_file/model_file.hpp"
#include "py_common.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::python {

namespace {

// The system and the text it was read from (a pickle rebuilds it from the
// text and the parameters' current values: Dask sends systems to workers).
struct PySystem {
  std::shared_ptr<System> system;
  std::string text, source;
};

PySystem FromText(const std::string& text, const std::string& source) {
  return PySystem{model_file::ParseModel(text, source), text, source};
}

PySystem FromFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) throw InvalidArgument(path + ": cannot read the model file");
  return FromText(text.str(), path);
}

py::tuple GetState(const PySystem& s) {
  std::vector<double> values;
  for (int j = 0; j < s.system->parameters(); ++j) values.push_back(s.system->ParameterValue(j));
  return py::make_tuple(s.text, s.source, values);
}

PySystem SetState(const py::tuple& t) {
  if (t.size() != 3) throw InvalidArgument("System: a pickle of 3 entries is needed");
  PySystem s = FromText(t[0].cast<std::string>(), t[1].cast<std::string>());
  const auto values = t[2].cast<std::vector<double>>();
  if (static_cast<int>(values.size()) != s.system->parameters())
    throw InvalidArgument("System: the pickle's parameters do not match its text");
  for (int j = 0; j < s.system->parameters(); ++j) s.system->SetParameterValue(j, values[j]);
  return s;
}

int IndexOf(const PySystem& s, const std::string& name) {
  const int j = s.system->ParameterIndex(name);
  if (j < 0)
    throw py::key_error("'" + name + "' is no parameter of " + model_file::ModelName(*s.system));
  return j;
}

void SetByName(PySystem& s, const std::string& name, const py::handle& value) {
  if (py::isinstance<py::bool_>(value) || !PyNumber_Check(value.ptr()) ||
      PyComplex_Check(value.ptr()))
    throw py::type_error(name + " must be a number, not " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  const int j = IndexOf(s, name);
  const double old = s.system->ParameterValue(j);
  s.system->SetParameterValue(j,
                              py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
  if (const std::string e = s.system->ValidationError(); !e.empty()) {
    s.system->SetParameterValue(j, old);  // the system stays valid
    throw InvalidArgument(name + ": " + e);
  }
}

std::string SystemRepr(const PySystem& s) {
  std::string r = "<System " + model_file::ModelName(*s.system) + ":";
  for (int j = 0; j < s.system->parameters(); ++j)
    r += " " + s.system->ParameterName(j) + "=" +
         py::repr(py::float_(s.system->ParameterValue(j))).cast<std::string>();
  return r + ">";
}

}  // namespace

std::unique_ptr<System> ModelSystemOf(const py::object& system) {
  if (!py::isinstance<PySystem>(system)) return nullptr;
  return system.cast<const PySystem&>().system->Clone();
}

void BindModel(py::module_& m) {
  py::class_<PySystem>(m, "System",
                       "A friction system written down in a model file (docs/model_files.md): "
                       "System.from_file(path) or System.from_text(text). Every function that "
                       "takes a system takes it. s['v'] reads a parameter, s['v'] = 0.3 sets it.")
      .def_static(
          "from_file", &FromFile, py::arg("path"),
          "The system of the model file at path; InvalidArgument '<file>:<line>: <problem>' "
          "for a bad file.")
      .def_static("from_text", &FromText, py::arg("text"), py::arg("source") = "<text>",
                  "The system of a model file's text; source names it in messages.")
      .def_property_readonly("name",
                             [](const PySystem& s) { return model_file::ModelName(*s.system); })
      .def_property_readonly("dimension", [](const PySystem& s) { return s.system->dimension(); })
      .def_property_readonly("contacts", [](const PySystem& s) { return s.system->contacts(); })
      .def_property_readonly("state_names",
                             [](const PySystem& s) {
                               std::vector<std::string> names;
                               for (int i = 0; i < s.system->dimension(); ++i)
                                 names.push_back(s.system->StateName(i));
                               return names;
                             })
      .def_property_readonly("parameters",
                             [](const PySystem& s) {
                               std::map<std::string, double> p;
                               for (int j = 0; j < s.system->parameters(); ++j)
                                 p[s.system->ParameterName(j)] = s.system->ParameterValue(j);
                               return p;
                             })
      .def(
          "copy",
          [](const PySystem& s) {
            return PySystem{s.system->Clone(), s.text, s.source};
          },
          "An independent copy (its parameters set apart from this one's).")
      .def("__getitem__",
           [](const PySystem& s, const std::string& name) {
             return s.system->ParameterValue(IndexOf(s, name));
           })
      .def("__setitem__", &SetByName)
      .def("__repr__", &SystemRepr)
      .def(py::pickle(&GetState, &SetState));
}

}  // namespace stickslip::python
