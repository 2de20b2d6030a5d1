#include "strandfem/core/quadrature.hpp"

#include <cmath>

namespace strandfem {

void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights) {
  points.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p1 = x, p0 = 1.0;
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    points[n - 1 - i] = x;
    weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
}

}  // namespace strandfem
