// The solution state of an analysis of a Model: element section histories and the contact set with its histories.
#pragma once
#include <vector>

#include "strandfem/solver/model.hpp"

namespace strandfem {

// What changes as a Model is solved, apart from the node states (which the analysis keeps, current and
// converged): the Model stays the definition, so one definition can serve several analyses and a state can be
// written and read back (checkpoints).
struct ModelState {
  std::vector<BeamElementState> elements;  // one per Model::elements, in the same order
  ContactSet contacts;                     // initialized by the analysis from Model::contact_settings

  // The state before any load: every element's initial section history, no contact points yet.
  static ModelState initial(const Model& model);

  // The interactions the solver drives beside the elements (wire contact when enabled).
  std::vector<Interaction*> interactions() {
    if (contacts.enabled()) return {&contacts};
    return {};
  }
  std::vector<const Interaction*> interactions() const {
    if (contacts.enabled()) return {&contacts};
    return {};
  }
};

}  // namespace strandfem
