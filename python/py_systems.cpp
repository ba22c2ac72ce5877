// The several-mass systems in the Python module (issue 32): ChainBlock and
// ChainParams (systems/chain, a chain of blocks on a belt) and CouplingParams
// (systems/mode_coupling, the 2-DOF brake model of Hoffmann et al. 2002),
// each validated at construction (ValueError naming the field and value).
// The functions that run any system are in py_system_runs.cpp.
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "chain/chain.hpp"
#include "mode_coupling/mode_coupling.hpp"
#include "py_common.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::python {

namespace {

using chain::Block;
using chain::ChainParams;
using mode_coupling::CouplingParams;

// ValueError (InvalidArgument) naming the field and its value unless ok.
void Require(bool ok, const std::string& where, const std::string& field, double value,
             const std::string& rule) {
  if (!ok) throw InvalidArgument(where + ": " + field + " = " + Repr(value) + " " + rule);
}

void CheckBlock(const Block& b, const std::string& where) {
  Require(b.m > 0 && std::isfinite(b.m), where, "m", b.m, "must be a finite number > 0");
  Require(b.c >= 0 && std::isfinite(b.c), where, "c", b.c, "must be a finite number >= 0");
  Require(b.k >= 0 && std::isfinite(b.k), where, "k", b.k, "must be a finite number >= 0");
  Params law = b.law;  // the law's own checks, with the block's damping
  law.beta = b.c / 2;
  const std::string e = ValidationError(law);
  if (!e.empty()) throw InvalidArgument(where + ": law: " + e);
}

// The chain's own checks (chain.cpp) after the Python-side ones.
void CheckChain(const ChainParams& p) {
  const int n = static_cast<int>(p.blocks.size());
  if (n < 1 || n > ModeSet::kMaxContacts)
    throw InvalidArgument("ChainParams: blocks = " + std::to_string(n) + " must lie in [1, " +
                          std::to_string(ModeSet::kMaxContacts) + "]");
  Require(p.v > 0 && std::isfinite(p.v), "ChainParams", "v", p.v, "must be a finite number > 0");
  Require(p.kc >= 0 && std::isfinite(p.kc), "ChainParams", "kc", p.kc,
          "must be a finite number >= 0");
  for (int i = 0; i < n; ++i)
    CheckBlock(p.blocks[i], "ChainParams: block " + std::to_string(i + 1));
  chain::Chain check(p);  // throws InvalidArgument naming the value
}

ChainParams MakeChain(const py::object& blocks, const std::optional<Params>& law,
                      std::optional<double> kc, std::optional<double> v) {
  ChainParams p;
  if (py::isinstance<py::int_>(blocks)) {
    const long n = blocks.cast<long>();
    if (n < 1 || n > ModeSet::kMaxContacts)
      throw InvalidArgument("ChainParams: blocks = " + std::to_string(n) + " must lie in [1, " +
                            std::to_string(ModeSet::kMaxContacts) + "]");
    p = chain::Uniform(static_cast<int>(n), law.value_or(Params()), kc.value_or(0.0));
  } else {
    if (law)
      throw InvalidArgument(
          "ChainParams: law is for n identical blocks (blocks an int); "
          "a list of ChainBlock carries each block's law");
    p.blocks = blocks.cast<std::vector<Block>>();  // TypeError for anything else
    p.kc = kc.value_or(0.0);
  }
  if (v) p.v = *v;
  CheckChain(p);
  return p;
}

std::string ChainRepr(const ChainParams& p) {
  return "ChainParams(" + std::to_string(p.blocks.size()) + " blocks, v=" + Repr(p.v) +
         ", kc=" + Repr(p.kc) + ")";
}

void CheckCoupling(const CouplingParams& p) {
  const char* names[] = {"beta", "k11", "k22", "k12", "gamma", "v"};
  const double values[] = {p.beta, p.k11, p.k22, p.k12, p.gamma, p.v};
  for (int j = 0; j < 6; ++j)
    Require(std::isfinite(values[j]), "CouplingParams", names[j], values[j], "must be finite");
  Require(p.beta >= 0, "CouplingParams", "beta", p.beta, "must be >= 0");
  Require(p.v > 0, "CouplingParams", "v", p.v, "must be > 0");
  Require(p.gamma >= 0, "CouplingParams", "gamma", p.gamma, "must be >= 0");
  Params law = p.law;
  law.beta = p.beta, law.v = p.v;
  const std::string e = ValidationError(law);
  if (!e.empty()) throw InvalidArgument("CouplingParams: law: " + e);
  mode_coupling::ModeCoupling check(p);  // the system's own checks
}

// The names of a system's state components and parameters.
template <typename S, typename P>
std::vector<std::string> ParameterNamesOf(const P& p) {
  const S s(p);
  std::vector<std::string> out;
  for (int j = 0; j < s.parameters(); ++j) out.push_back(s.ParameterName(j));
  return out;
}
template <typename S, typename P>
std::vector<std::string> StateNamesOf(const P& p) {
  const S s(p);
  std::vector<std::string> out;
  for (int i = 0; i < s.dimension(); ++i) out.push_back(s.StateName(i));
  return out;
}

void BindChain(py::module_& m) {
  py::class_<Block>(m, "ChainBlock",
                    "One block of a chain: m x'' + c x' + k x + springs = F(x' - v), F from its "
                    "law (law's beta and v are not read: c and the chain's v are).")
      .def(py::init([](double mass, double c, double k, const std::optional<Params>& law) {
             Block b;
             b.m = mass, b.c = c, b.k = k, b.law = law.value_or(Params());
             CheckBlock(b, "ChainBlock");
             return b;
           }),
           py::arg("m") = 1.0, py::arg("c") = 0.1, py::arg("k") = 1.0, py::arg("law") = py::none())
      .def_readwrite("m", &Block::m)
      .def_readwrite("c", &Block::c)
      .def_readwrite("k", &Block::k)
      .def_readwrite("law", &Block::law)
      .def("__repr__", [](const Block& b) {
        return "ChainBlock(m=" + Repr(b.m) + ", c=" + Repr(b.c) + ", k=" + Repr(b.k) +
               ", law=" + py::repr(py::cast(b.law)).cast<std::string>() + ")";
      });
  py::class_<ChainParams>(
      m, "ChainParams",
      "A chain of N blocks on a belt (systems/chain): m_i x_i'' + c_i x_i' + k_i x_i + kc sum_j "
      "(x_i - x_j) = F_i(x_i' - v), open ends. State (x1, x1', ..., xN, xN').")
      .def(py::init(&MakeChain), py::arg("blocks") = 2, py::arg("law") = py::none(),
           py::arg("kc") = py::none(), py::arg("v") = py::none(),
           "ChainParams(blocks=2, law=Params(), kc=0.0, v=law.v): `blocks` identical blocks with "
           "m = 1, c = 2 law.beta, k = 1 and law's friction; or blocks a list of ChainBlock "
           "(v default 0.25). Invalid values raise ValueError naming the field and value.")
      .def_readwrite("v", &ChainParams::v)
      .def_readwrite("kc", &ChainParams::kc)
      .def_readwrite("blocks", &ChainParams::blocks, "the blocks (a copy; assign a new list)")
      .def_property_readonly(
          "n", [](const ChainParams& p) { return static_cast<int>(p.blocks.size()); },
          "the number of blocks")
      .def_property_readonly("parameters", &ParameterNamesOf<chain::Chain, ChainParams>,
                             "the names continue_orbits' parameter takes")
      .def_property_readonly("state_names", &StateNamesOf<chain::Chain, ChainParams>)
      .def("validate", &CheckChain, "Raises ValueError naming the offending value.")
      .def("__repr__", &ChainRepr);
}

void BindCoupling(py::module_& m) {
  py::class_<CouplingParams>(
      m, "CouplingParams",
      "The 2-DOF mode-coupling brake model (systems/mode_coupling; Hoffmann et al. 2002): "
      "x'' + 2 beta x' + k11 x + k12 y = (1 - gamma y) F(x' - v), y'' + 2 beta y' + k12 x + "
      "k22 y = 0. State (x, x', y, y').")
      .def(py::init([](double beta, double k11, double k22, double k12, double gamma, double v,
                       const std::optional<Params>& law) {
             CouplingParams p;
             p.beta = beta, p.k11 = k11, p.k22 = k22, p.k12 = k12, p.gamma = gamma, p.v = v;
             p.law = law.value_or(Params());
             CheckCoupling(p);
             return p;
           }),
           py::arg("beta") = 0.02, py::arg("k11") = 1.0, py::arg("k22") = 1.5,
           py::arg("k12") = -0.3, py::arg("gamma") = 1.0, py::arg("v") = 0.5,
           py::arg("law") = py::none(),
           "Invalid values raise ValueError naming the field and value; law default Params() "
           "(its beta and v are not read).")
      .def_readwrite("beta", &CouplingParams::beta)
      .def_readwrite("k11", &CouplingParams::k11)
      .def_readwrite("k22", &CouplingParams::k22)
      .def_readwrite("k12", &CouplingParams::k12)
      .def_readwrite("gamma", &CouplingParams::gamma)
      .def_readwrite("v", &CouplingParams::v)
      .def_readwrite("law", &CouplingParams::law)
      .def_property_readonly("flutter_mu_k", &mode_coupling::FlutterMuK,
                             "mu_k* = -(D + 8 beta^2 (k11 + k22)) / (4 gamma k12), D = (k11 - "
                             "k22)^2 + 4 k12^2: Coulomb steady sliding flutters above it (nan "
                             "where gamma k12 >= 0)")
      .def_property_readonly("parameters",
                             &ParameterNamesOf<mode_coupling::ModeCoupling, CouplingParams>)
      .def_property_readonly("state_names",
                             &StateNamesOf<mode_coupling::ModeCoupling, CouplingParams>)
      .def("validate", &CheckCoupling, "Raises ValueError naming the offending value.")
      .def("__repr__", [](const CouplingParams& p) {
        return "CouplingParams(beta=" + Repr(p.beta) + ", k11=" + Repr(p.k11) +
               ", k22=" + Repr(p.k22) + ", k12=" + Repr(p.k12) + ", gamma=" + Repr(p.gamma) +
               ", v=" + Repr(p.v) + ", law=" + py::repr(py::cast(p.law)).cast<std::string>() + ")";
      });
}

}  // namespace

std::unique_ptr<System> SeveralMassSystemOf(const py::object& system) {
  if (py::isinstance<ChainParams>(system)) {
    const auto& p = system.cast<const ChainParams&>();
    CheckChain(p);  // attributes set after construction
    return std::make_unique<chain::Chain>(p);
  }
  if (py::isinstance<CouplingParams>(system)) {
    const auto& p = system.cast<const CouplingParams&>();
    CheckCoupling(p);
    return std::make_unique<mode_coupling::ModeCoupling>(p);
  }
  return nullptr;
}

void BindSystems(py::module_& m) {
  BindChain(m);
  BindCoupling(m);
}

}  // namespace stickslip::python
