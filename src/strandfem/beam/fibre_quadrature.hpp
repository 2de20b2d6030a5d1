// Fibre quadrature of a circular wire section: fibre positions and areas, and fibre strains from section strains.
#pragma once
#include <vector>

#include "strandfem/core/types.hpp"

namespace strandfem {

// One section point of the fibre quadrature: position (y, z) in the section axes 2 and 3, and its area.
struct Fibre {
  double y = 0, z = 0, area = 0;
};

// Polar quadrature of a disc: Gauss-Legendre rings (exact for the area, inertia and polar moment) times
// equally spaced sectors. 4 x 24 fibres put the fully plastic moment sum |z| A sigma_y within 0.6 % of
// 4/3 sigma_y r^3 whatever the bending direction.
std::vector<Fibre> disc_fibres(double radius, int rings = 4, int sectors = 24);

// Fibre strains from section strains [Gamma1, Gamma2, Gamma3, K1, K2, K3]:
//   eps = Gamma1 + K2 z - K3 y,  gamma12 = sqrt(k) Gamma2 - K1 z,  gamma13 = sqrt(k) Gamma3 + K1 y,
// with k the shear factor (so that an elastic section gives k G A, G J, E I exactly).
Eigen::Matrix<double, 3, 6> fibre_strain_operator(const Fibre& fibre, double shear_factor);

}  // namespace strandfem
