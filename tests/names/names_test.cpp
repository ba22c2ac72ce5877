// The name tables (names.hpp): every value of every named enum survives
// name -> enum -> name, names are unique within a table, and the names the
// output files carry are those of docs/formats.md.
#include "stickslip/names.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/continuation/palc.hpp"
#include "stickslip/estimates/estimates.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"

namespace stickslip {
namespace {

template <typename E>
void RoundTrip(const char* what) {
  std::set<std::string> seen;
  for (const NamedValue<E>& nv : EnumNames<E>::kTable) {
    E back{};
    ASSERT_TRUE(FromName(nv.name, &back)) << what << " " << nv.name;
    EXPECT_TRUE(back == nv.value) << what << " " << nv.name;
    EXPECT_STREQ(Name(back), nv.name) << what;
    EXPECT_TRUE(seen.insert(nv.name).second) << what << ": " << nv.name << " twice";
  }
  E unused{};
  EXPECT_FALSE(FromName("no such name", &unused)) << what;
}

TEST(Names, EveryTableRoundTrips) {
  RoundTrip<PalcStatus>("PalcStatus");
  RoundTrip<PointKind>("PointKind");
  RoundTrip<SpecialKind>("SpecialKind");
  RoundTrip<ContinuationStatus>("ContinuationStatus");
  RoundTrip<Fate>("Fate");
  RoundTrip<BasinStatus>("BasinStatus");
  RoundTrip<BoundStatus>("BoundStatus");
  RoundTrip<Region>("Region");
  RoundTrip<CurveKind>("CurveKind");
  RoundTrip<ChartStatus>("ChartStatus");
  RoundTrip<CurvePointType>("CurvePointType");
  RoundTrip<CurveEndKind>("CurveEndKind");
  RoundTrip<Codim2Label>("Codim2Label");
}

// The tables that replaced the enum-to-string switches (issue 19, item 5).
template <typename E>
void Covers(const char* what, E last) {
  RoundTrip<E>(what);
  EXPECT_EQ(NameCount<E>(), static_cast<size_t>(last) + 1) << what;
  for (size_t i = 0; i < NameCount<E>(); ++i)
    EXPECT_STRNE(Name(static_cast<E>(i)), "?") << what << " value " << i;
}

TEST(Names, FormerSwitchTablesRoundTripAndCoverTheirEnums) {
  Covers("Mode", Mode::kSlipAbove);
  Covers("LawKind", LawKind::kLeine);
  Covers("Integrator", Integrator::kCvode);
  Covers("Method", Method::kBdf);
  Covers("FlowStatus", FlowStatus::kSwitchCount);
  Covers("SwitchKind", SwitchKind::kTouch);
  Covers("OrbitKind", OrbitKind::kPureSlip);
  Covers("OrbitStatus", OrbitStatus::kModeChanged);
  Covers("SectionKind", SectionKind::kSurface);
  Covers("OrbitScanStatus", OrbitScanStatus::kCancelled);
  Covers("FigureFormat", FigureFormat::kSvg);
  Covers("AttractorKind", AttractorKind::kSettling);
  Covers("LyapunovStatus", LyapunovStatus::kContactOpen);
  Covers("SweepDirection", SweepDirection::kDown);
  Covers("Parameter", Parameter::kOmega);
  Covers("BranchStatus", BranchStatus::kSequenceEnded);
  Covers("SimulationStatus", SimulationStatus::kRowLimit);
  Covers("SimulationSection", SimulationSection::kNone);
  Covers("CurveKind", CurveKind::kTorus);
  Covers("Codim2Label", Codim2Label::kCusp);
  Covers("Codim2Method", Codim2Method::kPoint);
}

// Names the files and options carry (docs/formats.md, docs/cli.md).
TEST(Names, FormerSwitchNamesAreThoseOfTheDocs) {
  EXPECT_STREQ(Name(LawKind::kStribeck), "stribeck");
  EXPECT_STREQ(Name(Integrator::kCvode), "cvode");
  EXPECT_STREQ(Name(SpecialKind::kNone), "");
  EXPECT_STREQ(Name(SpecialKind::kPeriodDoubling), "PD");
  EXPECT_STREQ(Name(Codim2Label::kFoldFlip), "LPPD");
  EXPECT_STREQ(Name(Parameter::kOmega), "omega");
  EXPECT_STREQ(Name(FigureFormat::kPng), "png");
}

TEST(Names, TablesCoverEveryEnumerator) {
  // The enums are dense from 0: a table as long as the enum covers it.
  EXPECT_EQ(NameCount<CurvePointType>(), static_cast<size_t>(CurvePointType::kFold) + 1);
  EXPECT_EQ(NameCount<CurveEndKind>(), static_cast<size_t>(CurveEndKind::kCancelled) + 1);
  EXPECT_EQ(NameCount<Codim2Label>(), static_cast<size_t>(Codim2Label::kCusp) + 1);
  EXPECT_EQ(NameCount<PalcStatus>(), static_cast<size_t>(PalcStatus::kStartFailed) + 1);
  for (size_t i = 0; i < NameCount<CurvePointType>(); ++i)
    EXPECT_STRNE(Name(static_cast<CurvePointType>(i)), "?");
  for (size_t i = 0; i < NameCount<CurveEndKind>(); ++i)
    EXPECT_STRNE(Name(static_cast<CurveEndKind>(i)), "?");
}

// The names in the files (docs/formats.md: curves.tsv type, codim2.tsv label,
// the curves' "ends" comment).
TEST(Names, PrintedNamesAreThoseOfTheFileFormats) {
  EXPECT_STREQ(Name(CurvePointType::kNonsmoothFold), "nonsmooth-fold");
  EXPECT_STREQ(Name(Codim2Label::kGrazingFold), "GR-LP");
  EXPECT_STREQ(Name(CurveKind::kFold), "LP");
  CurveEnds e{{CurveEndKind::kBorder, ""}, {CurveEndKind::kStepTooSmall, "singular corrector"}};
  EXPECT_EQ(e.Text(), "border / step-too-small: singular corrector");
  e = {{CurveEndKind::kClosed, ""}, {CurveEndKind::kClosed, ""}};
  EXPECT_EQ(e.Text(), "closed");
  e = {{CurveEndKind::kNoStart, "F is not finite"}, {}};
  EXPECT_EQ(e.Text(), "start failed: F is not finite");
}

}  // namespace
}  // namespace stickslip
