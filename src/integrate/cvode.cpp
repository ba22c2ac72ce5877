#include "integrate/cvode.hpp"

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <utility>

#include "stickslip/errors.hpp"

namespace stickslip {

namespace {
void Check(int flag, const char* call) {
  if (flag < 0)
    throw ExternalError(std::string(call) + " failed with flag " + std::to_string(flag));
}
template <typename T>
T* CheckPtr(T* p, const char* call) {
  if (p == nullptr) throw ExternalError(std::string(call) + " returned NULL");
  return p;
}
}  // namespace

Cvode::Cvode(int n, Method method, double rtol, double atol, long max_steps, Rhs rhs, int nroots,
             RootFn g, void* user_data)
    : n_(n) {
  try {
    Check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
    y_ = CheckPtr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    tmp_ = CheckPtr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    N_VConst(0.0, y_);
    mem_ = CheckPtr(CVodeCreate(method == Method::kAdams ? CV_ADAMS : CV_BDF, ctx_), "CVodeCreate");
    Check(CVodeSetErrHandlerFn(mem_, &Cvode::ErrHandler, this), "CVodeSetErrHandlerFn");
    Check(CVodeInit(mem_, rhs, 0.0, y_), "CVodeInit");
    Check(CVodeSStolerances(mem_, rtol, atol), "CVodeSStolerances");
    Check(CVodeSetUserData(mem_, user_data), "CVodeSetUserData");
    Check(CVodeSetMaxNumSteps(mem_, max_steps), "CVodeSetMaxNumSteps");
    Check(CVodeSetMaxHnilWarns(mem_, -1), "CVodeSetMaxHnilWarns");
    if (method == Method::kAdams) {
      nls_ = CheckPtr(SUNNonlinSol_FixedPoint(y_, 0, ctx_), "SUNNonlinSol_FixedPoint");
      Check(CVodeSetNonlinearSolver(mem_, nls_), "CVodeSetNonlinearSolver");
    } else {
      A_ = CheckPtr(SUNDenseMatrix(n, n, ctx_), "SUNDenseMatrix");
      ls_ = CheckPtr(SUNLinSol_Dense(y_, A_, ctx_), "SUNLinSol_Dense");
      Check(CVodeSetLinearSolver(mem_, ls_, A_), "CVodeSetLinearSolver");
    }
    if (nroots > 0) Check(CVodeRootInit(mem_, nroots, g), "CVodeRootInit");
  } catch (...) {
    Release();
    throw;
  }
}

Cvode::~Cvode() { Release(); }

void Cvode::Release() {
  if (mem_) CVodeFree(&mem_);
  if (ls_) SUNLinSolFree(ls_);
  if (A_) SUNMatDestroy(A_);
  if (nls_) SUNNonlinSolFree(nls_);
  if (tmp_) N_VDestroy(tmp_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr;
  ls_ = nullptr;
  A_ = nullptr;
  nls_ = nullptr;
  tmp_ = y_ = nullptr;
  ctx_ = nullptr;
}

Cvode::Cvode(Cvode&& o) noexcept { *this = std::move(o); }

Cvode& Cvode::operator=(Cvode&& o) noexcept {
  if (this != &o) {
    Release();
    n_ = o.n_;
    std::swap(ctx_, o.ctx_);
    std::swap(y_, o.y_);
    std::swap(tmp_, o.tmp_);
    std::swap(mem_, o.mem_);
    std::swap(nls_, o.nls_);
    std::swap(A_, o.A_);
    std::swap(ls_, o.ls_);
    if (mem_) CVodeSetErrHandlerFn(mem_, &Cvode::ErrHandler, this);
  }
  return *this;
}

void Cvode::ErrHandler(int code, const char* /*module*/, const char* function, char* msg,
                       void* data) {
  if (code >= 0) return;  // warnings are not errors
  auto* self = static_cast<Cvode*>(data);
  self->last_error_ = std::string(function) + ": " + msg;
}

void Cvode::Reinit(double t0, const double* y0) {
  double* y = N_VGetArrayPointer(y_);
  for (int i = 0; i < n_; ++i) y[i] = y0[i];
  Check(CVodeReInit(mem_, t0, y_), "CVodeReInit");
}

void Cvode::RootInit(int nroots, RootFn g) {
  Check(CVodeRootInit(mem_, nroots, g), "CVodeRootInit");
}

void Cvode::SetMaxStep(double h) { Check(CVodeSetMaxStep(mem_, h), "CVodeSetMaxStep"); }

void Cvode::SetStopTime(double t) { Check(CVodeSetStopTime(mem_, t), "CVodeSetStopTime"); }

int Cvode::Advance(double tout, double* t) {
  last_error_.clear();
  return CVode(mem_, tout, y_, t, CV_NORMAL);
}

bool Cvode::Interpolate(double t, double* out) {
  if (CVodeGetDky(mem_, t, 0, tmp_) < 0) return false;
  const double* p = N_VGetArrayPointer(tmp_);
  for (int i = 0; i < n_; ++i) out[i] = p[i];
  return true;
}

void Cvode::RootInfo(int* roots_found) {
  Check(CVodeGetRootInfo(mem_, roots_found), "CVodeGetRootInfo");
}

double Cvode::LastStepStart() {
  double tn = 0, hu = 0;
  Check(CVodeGetCurrentTime(mem_, &tn), "CVodeGetCurrentTime");
  Check(CVodeGetLastStep(mem_, &hu), "CVodeGetLastStep");
  return tn - hu;
}

double Cvode::CurrentTime() {
  double tn = 0;
  Check(CVodeGetCurrentTime(mem_, &tn), "CVodeGetCurrentTime");
  return tn;
}

long Cvode::steps() const {
  long n = 0;
  CVodeGetNumSteps(mem_, &n);
  return n;
}

}  // namespace stickslip
