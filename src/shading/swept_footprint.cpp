#include "shading/swept_footprint.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "shading/circle_polygon.h"

namespace sg {

double swept_parallelogram_share(const std::vector<vec2>& centre, const std::vector<char>& valid,
                                 const mat2& D, double R) {
  const double area = std::fabs(glm::determinant(D));
  const int K = static_cast<int>(centre.size()) - 1;
  if (K < 1) return 0.0;
  const vec2 a = 0.5 * D[0], b = 0.5 * D[1];
  auto share_at = [&](const vec2& p) {
    if (area < 1e-30 * R * R) return dot(p, p) <= R * R ? 1.0 : 0.0;
    const vec2 quad[4] = {p - a - b, p + a - b, p + a + b, p - a + b};
    return std::fabs(circle_polygon_area(vec2(0), R, quad)) / area;
  };
  const double size = R + length(a) + length(b);
  double sum = 0;
  for (int k = 0; k < K; ++k) {
    if (!(valid[k] && valid[k + 1])) continue;
    const vec2 d = centre[k + 1] - centre[k];
    const int pieces = std::clamp(static_cast<int>(std::ceil(5 * length(d) / size)), 1, 64);
    for (int q = 0; q < pieces; ++q) {
      sum += boost::math::quadrature::gauss<double, 8>::integrate(
          [&](double s) { return share_at(centre[k] + s * d); }, double(q) / pieces,
          double(q + 1) / pieces);
    }
  }
  return sum / K;
}

}  // namespace sg
