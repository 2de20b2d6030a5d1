// Writes the bending-under-tension results of cyclic strand cases: deflection_curves.csv (core deflection
// along the strand at each cycle's peak load, from the clamp and from the load point, beside eq. 3.2 for EImax
// and EImin) and loops.csv (one row per hysteresis loop), and summarizes them for summary.json with the check of
// each peak's curve against eq. 3.2 and its rise from the load point.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/post/bending.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

class BendingWriter {
 public:
  // Active for strand cases with a cyclic step; otherwise every call does nothing.
  // resuming: the files are left alone until restore_state reopens them where the checkpoint stood.
  BendingWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming = false);
  bool active() const { return active_; }
  // transverse_load (N) and midspan_deflection (mm) of the converged increment, as in history.csv.
  void on_increment(const StaticAnalysis& analysis, const IncrementReport& report, double axial_force,
                    double transverse_load, double midspan_deflection);
  // Writes loops.csv; returns the summary block (references, loops, steadiness).
  nlohmann::json finish();
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);

 private:
  // deflection_curves.csv's rows and summary.json's checks of the core's curve at a cycle's peak load.
  void record_peak_curve(const StaticAnalysis& analysis, int cycle, double axial_force, double transverse_load);
  // Eqs. 3.1 and 3.2 on the span that bends: the strand less its clamps and its saddle (rigid), and a node's
  // distance x along it from the nearer clamp's edge (0 within a clamp, half the span within the saddle).
  double bent_span() const;
  double bent_x(double z) const;

  std::filesystem::path directory_;
  const CaseDefinition& case_;
  bool active_ = false;
  double ei_max_ = 0, ei_min_ = 0;   // N mm^2 (eqs. 1.1, 1.2)
  double wire_shear_stiffness_ = 0;  // N, for the EImin curve with the wires' shear flexibility
  int load_node_ = -1;               // core node that carries the transverse load
  // The curve's rise from the load point at one distance (the paper's Figs. 8, 9a, 15a), beside eq. 3.2's.
  struct LoadPointRise {
    double distance = 0, rise = 0, ei_max_rise = 0, ei_min_rise = 0;  // mm
  };
  static constexpr int kRiseDistances = 3;
  // Eq. 3.2's bounds against the core's curve at one cycle's peak load.
  struct CurveCheckAtPeak {
    int cycle = 0;
    CurveBoundsCheck all_nodes;          // every node but the clamped ends
    CurveBoundsCheck beyond_clamp_edge;  // nodes at least output.clamp_edge_offset from a clamp
    LoadPointRise from_load_point[kRiseDistances];
  };
  AppendedFile curves_;
  std::vector<LoadDeflectionPoint> history_;
  std::vector<CurveCheckAtPeak> curve_checks_;
};

}  // namespace strandfem
