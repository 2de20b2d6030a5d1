#include "strandfem/post/bending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strandfem {

double tensioned_beam_deflection(double load, double tension, double bending_stiffness, double span, double x) {
  const double k = std::sqrt(bending_stiffness / tension), u = x / k, a = 0.25 * span / k, t = std::tanh(a);
  // -sinh u + tanh(a) cosh u = [(t - 1) e^u + (t + 1) e^-u] / 2 with t - 1 = -2 e^-2a / (1 + e^-2a): written
  // with e^(u - 2a) it stays finite for slender strands (L/k of several hundred), where sinh and cosh overflow.
  const double e2a = std::exp(-2.0 * a);
  const double bracket = u - t + 0.5 * (-2.0 * std::exp(u - 2.0 * a) / (1.0 + e2a) + (t + 1.0) * std::exp(-u));
  return load * k / (2.0 * tension) * bracket;
}

double rise_from_load_point(const std::vector<DeflectionPoint>& curve, double load_z, double distance) {
  auto at = [&](double z) {
    if (z <= curve.front().z) return curve.front().deflection;
    if (z >= curve.back().z) return curve.back().deflection;
    const auto next = std::lower_bound(curve.begin(), curve.end(), z, [](const DeflectionPoint& p, double v) { return p.z < v; });
    const auto prev = next - 1;
    const double t = (z - prev->z) / (next->z - prev->z);
    return (1 - t) * prev->deflection + t * next->deflection;
  };
  return at(load_z) - 0.5 * (at(load_z - distance) + at(load_z + distance));
}

double tensioned_timoshenko_deflection(double load, double tension, double bending_stiffness, double shear_stiffness,
                                       double span, double x) {
  const double reduction = 1.0 - tension / shear_stiffness;
  return reduction * reduction * tensioned_beam_deflection(load, tension * reduction, bending_stiffness, span, x) +
         0.5 * load * x / shear_stiffness;
}

double tensioned_beam_midspan_deflection(double load, double tension, double bending_stiffness, double span) {
  const double k = std::sqrt(bending_stiffness / tension);
  return load / tension * (0.25 * span - k * std::tanh(0.25 * span / k));
}

double equivalent_bending_stiffness(double compliance, double tension, double span) {
  const double string_compliance = 0.25 * span / tension;
  if (!(compliance > 0)) return std::numeric_limits<double>::infinity();
  if (compliance >= string_compliance) return 0.0;
  // Compliance falls monotonically from L/(4T) (k -> 0) to 0 (k -> infinity): bisect on log k.
  auto compliance_at = [&](double k) { return (0.25 * span - k * std::tanh(0.25 * span / k)) / tension; };
  double low = 1e-9 * span, high = 1e9 * span;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(low * high);
    (compliance_at(mid) > compliance ? low : high) = mid;
  }
  const double k = std::sqrt(low * high);
  return tension * k * k;
}

CurveBoundsCheck check_curve_bounds(const std::vector<CurveSample>& curve, double from_clamp) {
  CurveBoundsCheck check;
  for (const CurveSample& s : curve) {
    if (!(s.x > 0) || s.x < from_clamp) continue;
    ++check.nodes;
    const double excess = s.deflection - s.upper_bound, shortfall = s.lower_bound - s.deflection;
    if (excess <= 0 && shortfall <= 0) ++check.within;
    if (excess > check.largest_excess) {
      check.largest_excess = excess;
      check.largest_excess_x = s.x;
      check.largest_excess_relative = s.upper_bound > 0 ? excess / s.upper_bound : 0.0;
    }
    if (shortfall > check.largest_shortfall) {
      check.largest_shortfall = shortfall;
      check.largest_shortfall_x = s.x;
    }
  }
  return check;
}

namespace {

// Area of the polygon through the points, closed by a straight line from the last to the first.
double polygon_area(const std::vector<const LoadDeflectionPoint*>& polygon) {
  double twice_area = 0;
  for (std::size_t j = 0; j < polygon.size(); ++j) {
    const LoadDeflectionPoint& a = *polygon[j];
    const LoadDeflectionPoint& b = *polygon[(j + 1) % polygon.size()];
    twice_area += a.deflection * b.load - b.deflection * a.load;
  }
  return 0.5 * std::abs(twice_area);
}

}  // namespace

std::vector<HysteresisLoop> hysteresis_loops(const std::vector<LoadDeflectionPoint>& history) {
  std::vector<HysteresisLoop> loops;
  // The previous complete cycle's return half, its peak first, and the index of the point after its end.
  std::vector<const LoadDeflectionPoint*> previous_return;
  std::size_t previous_end = 0;
  for (std::size_t i = 0; i < history.size();) {
    const int cycle = history[i].cycle;
    if (cycle == 0) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < history.size() && history[end].cycle == cycle) ++end;
    // A complete cycle has both halves; the start is the point before its first increment.
    const bool complete = end > i + 1 && history[end - 1].returning && !history[i].returning;
    if (complete && i > 0) {
      std::vector<const LoadDeflectionPoint*> polygon = {&history[i - 1]};
      for (std::size_t j = i; j < end; ++j) polygon.push_back(&history[j]);
      HysteresisLoop loop;
      loop.cycle = cycle;
      const LoadDeflectionPoint& start = *polygon.front();
      std::size_t peak = 0;
      for (std::size_t j = 0; j < polygon.size(); ++j)
        if (!polygon[j]->returning || j == 0) peak = j;
      loop.peak_load = polygon[peak]->load;
      loop.peak_deflection = polygon[peak]->deflection;
      loop.peak_tension = polygon[peak]->tension;
      loop.start_deflection = start.deflection;
      loop.end_deflection = polygon.back()->deflection;
      loop.area = polygon_area(polygon);
      if (!previous_return.empty() && previous_end == i && loops.back().cycle + 1 == cycle) {
        // polygon[0] (this cycle's start) is the previous return half's last point.
        std::vector<const LoadDeflectionPoint*> return_loop = previous_return;
        return_loop.insert(return_loop.end(), polygon.begin() + 1, polygon.begin() + static_cast<std::ptrdiff_t>(peak) + 1);
        loop.has_return_loop = true;
        loop.return_loop_area = polygon_area(return_loop);
        loop.return_loop_friction_dissipation = polygon[peak]->friction_dissipation - previous_return.front()->friction_dissipation;
      }
      previous_return.assign(polygon.begin() + static_cast<std::ptrdiff_t>(peak), polygon.end());
      previous_end = end;
      loop.friction_dissipation = polygon.back()->friction_dissipation - start.friction_dissipation;
      auto slope = [](const LoadDeflectionPoint& a, const LoadDeflectionPoint& b) {
        const double dy = b.deflection - a.deflection;
        return dy != 0 ? (b.load - a.load) / dy : std::numeric_limits<double>::infinity();
      };
      loop.secant_stiffness = slope(start, *polygon[peak]);
      loop.loading_tangent = slope(start, *polygon[1]);
      if (peak + 1 < polygon.size()) loop.unloading_tangent = slope(*polygon[peak], *polygon[peak + 1]);
      loops.push_back(loop);
    }
    i = end;
  }
  return loops;
}

CycleChange cycle_change(const HysteresisLoop& previous, const HysteresisLoop& current) {
  auto relative = [](double before, double now, double scale) { return scale > 0 ? (now - before) / scale : 0.0; };
  const double deflection_scale =
      std::max(std::abs(current.peak_deflection - current.start_deflection), std::abs(previous.peak_deflection - previous.start_deflection));
  CycleChange change;
  change.area = relative(previous.area, current.area, std::max(std::abs(previous.area), std::abs(current.area)));
  change.friction_dissipation = relative(previous.friction_dissipation, current.friction_dissipation,
                                         std::max(std::abs(previous.friction_dissipation), std::abs(current.friction_dissipation)));
  change.peak_deflection = relative(previous.peak_deflection, current.peak_deflection, deflection_scale);
  return change;
}

bool loop_is_steady(const HysteresisLoop& previous, const HysteresisLoop& current, double tolerance) {
  const CycleChange change = cycle_change(previous, current);
  return std::abs(change.area) <= tolerance && std::abs(change.peak_deflection) <= tolerance;
}

}  // namespace strandfem
