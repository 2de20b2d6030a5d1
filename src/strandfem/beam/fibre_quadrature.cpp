#include "strandfem/beam/fibre_quadrature.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "strandfem/core/quadrature.hpp"

namespace strandfem {

std::vector<Fibre> disc_fibres(double radius, int rings, int sectors) {
  if (!(radius > 0) || rings < 1 || sectors < 3) throw std::invalid_argument("disc_fibres: bad radius or counts");
  std::vector<double> nodes, weights;
  gauss_legendre(rings, nodes, weights);
  std::vector<Fibre> fibres;
  const double sector_angle = 2.0 * std::numbers::pi / sectors;
  for (int i = 0; i < rings; ++i) {
    // Integral over r in [0, R] of f(r) r dr.
    const double r = 0.5 * radius * (nodes[i] + 1.0);
    const double ring_weight = 0.5 * radius * weights[i] * r;
    for (int j = 0; j < sectors; ++j) {
      const double angle = (j + 0.5) * sector_angle;
      fibres.push_back({r * std::cos(angle), r * std::sin(angle), ring_weight * sector_angle});
    }
  }
  return fibres;
}

Eigen::Matrix<double, 3, 6> fibre_strain_operator(const Fibre& f, double shear_factor) {
  const double s = std::sqrt(shear_factor);
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  B(0, 0) = 1.0;
  B(0, 4) = f.z;
  B(0, 5) = -f.y;
  B(1, 1) = s;
  B(1, 3) = -f.z;
  B(2, 2) = s;
  B(2, 3) = f.y;
  return B;
}

}  // namespace strandfem
