// Private to src/: a move-only owner of one CVODE integrator with root finding (SUNDIALS 6.4),
// after examples/cvode/serial/cvRoberts_dns.c: every return code is checked at
// the call site; a failed set-up call throws ExternalError naming the call.
#pragma once

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>

#include <string>

#include "stickslip/flow/flow_options.hpp"  // Method

namespace stickslip {

class Cvode {
 public:
  using Rhs = CVRhsFn;
  using RootFn = CVRootFn;

  // n states, nroots root functions (0 for none); user_data goes to rhs and g.
  Cvode(int n, Method method, double rtol, double atol, long max_steps, Rhs rhs, int nroots,
        RootFn g, void* user_data);
  ~Cvode();
  Cvode(const Cvode&) = delete;
  Cvode& operator=(const Cvode&) = delete;
  Cvode(Cvode&& other) noexcept;
  Cvode& operator=(Cvode&& other) noexcept;

  // Restart at (t0, y0); y0 has n entries. Root finding stays on.
  void Reinit(double t0, const double* y0);
  // A new number of root functions (CVodeRootInit again: it reallocates).
  void RootInit(int nroots, RootFn g);
  void SetStopTime(double t);
  // The largest step (0: none).
  void SetMaxStep(double h);
  // One call of CVode in CV_NORMAL mode; returns its flag, state in y().
  int Advance(double tout, double* t);
  // Interpolated state at t inside the last step (CVodeGetDky, k = 0).
  bool Interpolate(double t, double* out);
  void RootInfo(int* roots_found);
  // [tn - hu, tn]: the last step, where Interpolate is valid.
  double LastStepStart();
  // CVODE's internal time tn (also after a failed call).
  double CurrentTime();

  double* y() { return N_VGetArrayPointer(y_); }
  int size() const { return n_; }
  // The last error SUNDIALS reported, with the function that reported it.
  const std::string& last_error() const { return last_error_; }
  long steps() const;

 private:
  static void ErrHandler(int code, const char* module, const char* function, char* msg, void* data);
  void Release();

  int n_ = 0;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector tmp_ = nullptr;
  void* mem_ = nullptr;
  SUNNonlinearSolver nls_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
  std::string last_error_;
};

}  // namespace stickslip
