// Gauss-Legendre quadrature rules.
#pragma once
#include <vector>

namespace strandfem {

// Points (ascending) and weights of the n-point Gauss-Legendre rule on [-1, 1] (Newton on the Legendre polynomial).
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights);

}  // namespace strandfem
