// The radiance of a pixel whose normals follow a 2D Gaussian on the NDF plane: the
// shading step of every method that filters normals into a Gaussian (LEAN mapping, Olano
// and Baker 2010; the NDF of Podee et al. 2021, Sec. 3.4, without its time integral).
//
// With centre n_c (NDF-plane point, minus the mean slope) and covariance Sigma:
//  - light: the RDF is the Gaussian of centre Phi(n_c) and covariance J_c Sigma J_c^T on
//    the light plane (Podee Eqs. 11-16, shading/rdf.h); its mass in the light disk of
//    radius tan(rho) (gaussian_disk.h) is the fraction that mirrors the light. Zero when
//    the centre reflection points away from the light (r . L <= 0), where the gnomonic
//    linearisation does not exist, or when the disk lies beyond 10 major standard
//    deviations (mass < 1e-22).
//  - below the horizon: r_y(n) linearised at n_c in the same way (first order, as Eq. 11),
//    r_y ~ r_y(n_c) + g . (n - n_c), g = (dr_y/dn_x, dr_y/dn_z); the Gaussian's mass where
//    that is <= 0 is Phi(-r_y(n_c) / sqrt(g^T Sigma g)).
//  - Fresnel: F of the centre normal (Schlick with n_c's unit normal, or 1).
// combine_weights (radiance.h) turns the fractions into the spec's radiance weights.
#pragma once

#include "math/vec.h"
#include "scene/model.h"

namespace sg {

struct GaussianNdfShading {
  double in_light = 0;           // fraction reflecting into the light disk
  double below = 0;              // fraction reflecting below the horizon
  double F = 1;                  // Fresnel factor of the centre normal
  RadianceWeights weights{0.0};  // combine_weights(F, in_light, below, centre reflection)
};

// `view`: unit direction from the water point towards the camera. `cov` must be symmetric
// positive semi-definite (a zero covariance is a single normal).
GaussianNdfShading shade_gaussian_ndf(const SceneModel& m, const vec3& view, const vec2& centre,
                                      const mat2& cov);

}  // namespace sg
