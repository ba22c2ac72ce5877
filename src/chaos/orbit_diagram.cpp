// The orbit diagram's sweeps (chaos/orbit_diagram.hpp): each piece of each
// direction a task of a bounded pool, continuing from its last state; the
// calling thread polls cancellation and reports progress.
#include "stickslip/chaos/orbit_diagram.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "numerics/numbers.hpp"
#include "parallel/pool.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {

std::string OrbitDiagramOptions::ValidationError() const {
  if (!(std::isfinite(from) && std::isfinite(to)) || from == to)
    return "from = " + Num(from) + " and to = " + Num(to) + " must be finite and differ";
  if (n < 2 || n > kMaxValues)  // the text's 1e6 is kMaxValues
    return "n = " + std::to_string(n) + " must lie in [2, 1e6]";
  if (!up && !down) return "no sweep direction";
  if (static_cast<double>(n) * iterate.keep * (up + down) > kMaxPoints)
    return "n x keep x directions = " + Num(static_cast<double>(n) * iterate.keep * (up + down)) +
           " section points is more than " + Num(kMaxPoints) + " (held in memory)";
  if (chunks < 1 || chunks > n) return "chunks = " + std::to_string(chunks) + " must lie in [1, n]";
  if (threads < 0) return "threads = " + std::to_string(threads) + " must be >= 0";
  if (!(max_amplitude > 0)) return "max_amplitude = " + Num(max_amplitude) + " must be > 0";
  return iterate.ValidationError();
}

namespace {

// At rest on the belt: every contact's velocity on its surface (OntoSurface),
// the rest 0, the clocks at phase 0.
FlowPoint OnTheBelt(const System& s) {
  FlowPoint z{0, Eigen::VectorXd::Zero(s.dimension()), ModeSet()};
  for (int i = 0; i < s.contacts(); ++i) OntoSurface(s.Contact(i), z.z);
  z.mode = ModeOf(s, z.z);
  return z;
}

// The last value's end as this value's start: a sticking contact moves onto
// its surface (the belt's speed may be the swept parameter), and the mode is
// Filippov's at the new value.
FlowPoint Carried(const System& s, FlowPoint z) {
  OntoStickSurfaces(s, z.mode, z.z);
  z.t = 0;
  z.mode = ModeOf(s, z.z);
  return z;
}

PoincareSection SectionAt(const System& s, const OrbitDiagramOptions& o, const FlowPoint& z) {
  if (s.clocks() > 0) return PoincareSection::Stroboscopic(s, z.z, 1);
  PoincareSection p;
  p.kind = SectionKind::kSurface;
  p.surface = o.surface ? *o.surface : MaximaSection(s);
  return p;
}

SectionPoint RestPoint(const System& s, const FlowPoint& z) {
  SectionPoint p;
  p.z = z.z.head(s.tangent_dimension());
  p.mode = z.mode;
  return p;
}

// One direction's sweep over `cols` (in sweep order); never throws.
void Sweep(const System& base, int j, const OrbitDiagramOptions& o,
           std::vector<DiagramColumn*> cols, const std::atomic<bool>& stop,
           std::atomic<int>& done) {
  bool restart = true;
  FlowPoint z;
  std::unique_ptr<System> s = base.Clone();
  for (DiagramColumn* c : cols) {
    if (stop.load(std::memory_order_relaxed)) return;
    try {
      s->SetParameterValue(j, c->value);
      const std::string e = s->ValidationError();
      if (!e.empty()) throw InvalidArgument(e);
      z = Carried(*s, restart ? OnTheBelt(*s) : z);
      c->run = IterateSection(
          *s, z, SectionAt(*s, o, z), o.iterate,
          [&stop] { return stop.load(std::memory_order_relaxed); }, o.max_amplitude);
      if (c->run.status == LyapunovStatus::kRest)  // steady sliding: its point, one row
        c->run.points.assign(1, RestPoint(*s, c->run.end));
      restart = c->run.status != LyapunovStatus::kDone && c->run.status != LyapunovStatus::kRest;
      z = c->run.end;
    } catch (const std::exception& e) {  // no exception leaves the thread
      c->run.status = LyapunovStatus::kFlowFailed;
      c->run.message = e.what();
      restart = true;
    } catch (...) {
      c->run.status = LyapunovStatus::kFlowFailed;
      c->run.message = "unknown exception";
      restart = true;
    }
    c->computed = c->run.status != LyapunovStatus::kCancelled;
    done.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace

OrbitDiagram ComputeOrbitDiagram(const ForcedBeltParams& base, const OrbitDiagramOptions& o) {
  if (const std::string ae = AxisError(o.axis, base.base.law, true); !ae.empty())
    throw InvalidArgument(ae);
  for (double v : {o.from, o.to}) {
    ForcedBeltParams p = base;
    o.axis.Set(p, v);
    const std::string pe = ValidationError(p);
    if (!pe.empty()) throw InvalidArgument(pe);
  }
  return ComputeOrbitDiagram(ForcedBelt(base), o.axis.index(), o);
}

OrbitDiagram ComputeOrbitDiagram(const System& base, int j, const OrbitDiagramOptions& o) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (j < 0 || j >= base.parameters())
    throw InvalidArgument("parameter index " + std::to_string(j) + " must lie in [0, " +
                          std::to_string(base.parameters() - 1) + "]");
  // A parameter the system does not depend on: every column the same (as AxisError above).
  if (const std::string pe = base.ParameterError(j); !pe.empty()) throw InvalidArgument(pe);
  if (base.clocks() > 1) throw InvalidArgument("a system with more than one clock");
  if (base.clocks() == 0 && !o.surface) MaximaSection(base);  // its steady sliding, once
  for (double v : {o.from, o.to}) {
    std::unique_ptr<System> s = base.Clone();
    s->SetParameterValue(j, v);
    const std::string pe = s->ValidationError();
    if (!pe.empty()) throw InvalidArgument(base.ParameterName(j) + " = " + Num(v) + ": " + pe);
  }
  const auto t0 = std::chrono::steady_clock::now();
  OrbitDiagram d;
  const int n = o.n;
  d.columns.resize(static_cast<size_t>(n) * (o.up + o.down));
  std::vector<DiagramColumn*> up, down;
  for (int i = 0; i < n; ++i) {
    const double lo = std::min(o.from, o.to), hi = std::max(o.from, o.to);
    const double v = i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1);
    if (o.up) {
      DiagramColumn& c = d.columns[i];
      c.direction = SweepDirection::kUp, c.value = v;
      up.push_back(&c);
    }
    if (o.down) {
      DiagramColumn& c = d.columns[(o.up ? n : 0) + (n - 1 - i)];
      c.direction = SweepDirection::kDown, c.value = v;
    }
  }
  if (o.down)
    for (int i = 0; i < n; ++i) down.push_back(&d.columns[(o.up ? n : 0) + i]);
  std::atomic<bool> stop{false};
  std::atomic<int> done{0};
  // Each direction in o.chunks pieces, piece c the values [n c / chunks, n (c + 1) / chunks),
  // run on a bounded pool (parallel/pool.hpp).
  std::vector<std::vector<DiagramColumn*>> pieces;
  for (auto* cols : {&up, &down})
    for (long long c = 0; c < o.chunks && !cols->empty(); ++c) {
      const auto b = cols->begin();
      pieces.emplace_back(b + n * c / o.chunks, b + n * (c + 1) / o.chunks);
    }
  const int total = static_cast<int>(d.columns.size());
  const PoolRun pool = RunPool(
      static_cast<int>(pieces.size()), o.threads,
      [&](int k) { Sweep(base, j, o, pieces[k], stop, done); }, stop,
      [&] {
        if (o.cancelled && o.cancelled()) return true;
        if (o.progress) o.progress(done.load(), total);
        return false;
      });
  d.threads = pool.threads;
  d.error = pool.error;
  d.cancelled = stop.load();
  for (const DiagramColumn& c : d.columns) {
    if (c.computed && !c.settled())
      ++(c.run.status == LyapunovStatus::kContactOpen ? d.contact_lost : d.failed);
    d.steps += c.run.steps;
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

}  // namespace stickslip
