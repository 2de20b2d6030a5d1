// All contact points of a model: automatic detection, evaluation at a state, history commit, counts.
#pragma once
#include <array>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "strandfem/contact/contact_point.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

// A slave element in line contact with one master wire: its Gauss points project onto whichever
// candidate master element holds their foot point, so force crossing master element ends is neither
// lost nor counted twice.
struct LineContactGroup {
  int slave_element = -1;        // mesh element index
  int wire_b = -1;
  std::vector<int> candidates;   // element indices within wire b
};

class ContactSet final : public Interaction {
 public:
  // Searches the reference configuration and creates the contact points. Throws std::invalid_argument
  // for bad settings.
  void initialize(const Mesh& mesh, const ContactSettings& settings);
  bool enabled() const { return settings_.enabled; }
  const ContactSettings& settings() const { return settings_; }

  // Evaluates every point at `state` from the committed histories (no history is written).
  void evaluate(const Mesh& mesh, const std::vector<NodeState>& state, bool with_tangent) override;
  void contributions(const Mesh& mesh, std::vector<PairContribution>& out) const override;
  const std::vector<ContactPoint>& points() const { return points_; }
  const std::vector<ContactResponse>& responses() const { return responses_; }
  // Mesh nodes a0, a1, a2, b0, b1, b2 of a point as last evaluated (b: the master element used).
  std::array<int, 6> nodes_of(const Mesh& mesh, int point) const;
  // Mesh elements (slave, master) of a point as last evaluated.
  std::pair<int, int> elements_of(const Mesh& mesh, int point) const;

  // Active set and held friction states (see ContactPoint::active, ::friction_mode). begin_increment: the
  // points closed at the last converged state are active, friction is free; activate_closed, after each
  // accepted iterate: closed points become active and hold their stick/slip state; release_tensile, once
  // Newton has converged: releases points in tension and switches held friction states that the trial
  // force contradicts; returns how many changed (0: the increment has converged).
  void begin_increment(bool loading_continues) override;
  void accept_iterate(const Mesh& mesh) override;
  bool element_pairs_grew() override {
    const bool grew = pairs_grew_;
    pairs_grew_ = false;
    return grew;
  }
  int changes_at_convergence() override { return release_tensile(); }
  int augment_at_convergence() override { return augment_stick(); }
  void return_to_converged_round() override { points_ = converged_round_; }
  // A point that carried less than the full penalty stiffness where a correction starts (open, or within the
  // normal smoothing band) may close in it, but a correction that presses it deeper than kDeepClosing closing
  // depths is cut to where the deepest such point just reaches one closing depth: its tangent knew nothing of that
  // point, and the penalty force there would be the tangent's error, not the strand's.
  void begin_correction() override;
  double admissible_fraction() const override;
  void revert() override {}  // working states are rebuilt from the histories by begin_increment
  void activate_closed();
  // Checkpoints: everything a resumed run needs to continue from the last converged increment. restore_state
  // replaces the points found by initialize() and evaluates them at `state` (the checkpoint's converged state).
  void save_state(ArchiveWriter& out) const override;
  void restore_state(ArchiveReader& in, const Mesh& mesh, const std::vector<NodeState>& state) override;
  int release_tensile();
  // The largest |normal force| over the points of each kind at the last evaluation: [point, line].
  std::array<double, 2> largest_normal_forces() const;
  // Augmented stick (ContactSettings::stick_augmentations): once the stick points of one of them have moved apart by
  // more than the tolerance, every sticking crossing under pressure, and every sticking line point that carries a tenth
  // of the largest line load or more, takes its elastic slip into its stick offset (Newton goes on). Returns how many
  // points changed; 0 when none is above the tolerance or the rounds are spent.
  int augment_stick();
  int augmentation_rounds() const { return augmentation_rounds_; }

  // Converged increment at `state`: writes histories (stick points, slip), keeps each crossing's element pair
  // (the centre of its next location), re-runs the search when nodes moved more than half the margin. Returns true
  // when element_pairs() changed (the tangent's pattern must be rebuilt): a pair is needed that it lacks, or
  // too many of its pairs are no longer needed.
  bool commit(const Mesh& mesh, const std::vector<NodeState>& state) override;

  // Mesh element pairs that contact may couple (the sparsity pattern): those of points closed or nearly so
  // (ContactSettings::pattern_margin), for a crossing also the pair it is evaluated on now, and pairs no longer
  // needed until they are a quarter of the needed ones (a change costs an analysis and a factorization).
  const std::vector<std::pair<int, int>>& element_pairs() const override { return element_pairs_; }
  // Lateral pairs: (slave element, master wire) line-contact groups (the paper's "contact pairs").
  int lateral_pair_count() const { return static_cast<int>(groups_.size()); }
  // Radial contacts: crossings of wires in point contact.
  int radial_point_count() const;
  int line_point_count() const { return static_cast<int>(points_.size()) - radial_point_count(); }
  int search_count() const { return searches_; }
  // Work of friction over all slip up to the last commit, N mm.
  double dissipated_energy() const;
  double commit_stabilization_energy() const override { return commit_stabilization_energy_; }
  void set_stabilization(double fraction, const Mesh& mesh, const std::vector<NodeState>& state) override;

 private:
  void search(const Mesh& mesh, const std::vector<NodeState>& state);
  // Writes one point's history from its response at the converged state (see commit()).
  void commit_point(const Mesh& mesh, const std::vector<NodeState>& state, std::size_t index);
  void add_line_points(const Mesh& mesh, int group);
  void add_crossing(const Mesh& mesh, int element_a, int element_b, double xi, double eta);
  void set_point_properties(const Mesh& mesh, ContactPoint& p, const Vec3& reference_position);
  double sliding_stabilization(const ContactPoint& p) const;
  // Where point i touches both surfaces in its last evaluation (after commit_point has set its element):
  // wire coordinates of slave and master and section-fixed directions, as stick and start points are stored.
  using SurfacePoints = std::tuple<double, double, Vec3, Vec3>;
  SurfacePoints surface_points(const Mesh& mesh, const std::vector<NodeState>& state, std::size_t i) const;
  // The stabilization's spring anchors (ContactPoint::start_a...) at the contact points of the last evaluation.
  void set_start_points(const Mesh& mesh, const std::vector<NodeState>& state);
  void evaluate_point(const Mesh& mesh, const std::vector<NodeState>& state, int index, bool with_tangent,
                      ContactResponse& response) const;
  double initial_offset(const Mesh& mesh, const ContactPoint& p) const;
  double reference_gap(const Mesh& mesh, const ContactPoint& p) const;
  std::vector<std::pair<int, int>> collect_element_pairs(const Mesh& mesh) const;
  // Pattern membership from the last evaluation: points closed or within the margin enter; with `may_leave`,
  // open points beyond twice the margin leave. Returns true when a point entered.
  bool update_pattern_membership(bool may_leave);

  ContactSettings settings_;
  std::vector<ContactPoint> points_;
  std::vector<ContactResponse> responses_;
  std::vector<LineContactGroup> groups_;
  std::map<std::pair<int, int>, int> group_of_;             // (slave mesh element, wire b) -> group
  std::map<std::pair<int, int>, ContactKind> wire_pair_kind_;  // (lower wire, higher wire)
  std::vector<std::pair<int, int>> element_pairs_;
  std::vector<double> correction_start_gaps_;  // gaps of the iterate the current Newton correction starts from
  std::vector<char> in_pattern_;  // per point: its element pairs are in the pattern (a line point: its group's)
  bool pairs_grew_ = false;
  std::vector<NodeState> reference_;  // the mesh's stress-free state (overlap offsets are measured there)
  std::vector<Vec3> searched_positions_;
  int searches_ = 0;
  int augmentation_rounds_ = 0;  // augment_stick rounds in this increment
  std::vector<ContactPoint> converged_round_;  // the points before the last augmentation round (augment_stick)
  double commit_stabilization_energy_ = 0;  // see commit_stabilization_energy()
};

}  // namespace strandfem
