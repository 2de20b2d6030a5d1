#include "strandfem/solver/model_state.hpp"

namespace strandfem {

ModelState ModelState::initial(const Model& model) {
  ModelState state;
  state.elements.reserve(model.elements.size());
  for (const BeamElement& e : model.elements) state.elements.push_back(e.initial_state());
  return state;
}

}  // namespace strandfem
