#include "strandfem/analysis/load_protocol.hpp"

#include <map>
#include <tuple>

namespace strandfem {

std::vector<LoadRamp> expand_load_steps(const std::vector<LoadStep>& steps) {
  using Key = std::tuple<int, int, int>;  // node, component, kind
  std::map<Key, double> totals;           // every action's total so far (0 before its first step)
  std::vector<LoadRamp> ramps;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const LoadStep& step = steps[s];
    if (step.cycles <= 0) {
      ramps.push_back({step.name, step.increments, step.actions, {static_cast<int>(s), 0, false}});
    } else {
      std::vector<NodalAction> back = step.actions;
      for (NodalAction& a : back) {
        const auto it = totals.find({a.node, a.component, a.kind});
        a.value = it == totals.end() ? 0.0 : it->second;
      }
      for (int cycle = 1; cycle <= step.cycles; ++cycle) {
        const std::string label = step.name + " cycle " + std::to_string(cycle);
        ramps.push_back({label + " out", step.increments, step.actions, {static_cast<int>(s), cycle, false}});
        ramps.push_back({label + " back", step.increments, back, {static_cast<int>(s), cycle, true}});
      }
    }
    for (const NodalAction& a : ramps.back().actions) totals[{a.node, a.component, a.kind}] = a.value;
  }
  return ramps;
}

}  // namespace strandfem
