#pragma once

#include <glm/vec3.hpp>

namespace speculum::render::math {

// The GGX (Trowbridge–Reitz) microfacet lobe of a rough mirror, isotropic, in the local frame of the macro
// surface: z is the normal, so a direction's z is its cosine to the normal. α = roughness² (as the scene
// file's roughness is defined); α > 0 throughout: a roughness of 0 is a perfect mirror, which has no lobe to
// sample (callers reflect sharply instead). The Fresnel factor is left out (F = 1): the mirror and reflector
// shaders weight the whole reflection by their own Schlick R, outside the lobe.

// D(h): the distribution of microfacet normals, normalised so that ∫ D(h) (n·h) dω_h = 1. 0 below the
// surface.
double ggxD(const glm::dvec3& h, double alpha);

// Smith's Λ(w) for GGX: (−1 + √(1 + α² tan²θ)) / 2; infinite at and below the horizon.
double smithLambda(const glm::dvec3& w, double alpha);

// The masking of one direction: G1(w) = 1 / (1 + Λ(w)); 0 at and below the horizon.
double smithG1(const glm::dvec3& w, double alpha);

// The joint masking-shadowing of the view v and light l, in the height-correlated Smith form
// G2 = 1 / (1 + Λ(v) + Λ(l)) (Heitz 2014, "Understanding the masking-shadowing function"): more accurate
// than the separable product G1(v)·G1(l), which counts a microfacet hidden from both directions twice.
// 0 when either lies at or below the horizon.
double smithG2(const glm::dvec3& v, const glm::dvec3& l, double alpha);

// The estimator's weight of one visible-normal sample: f·(n·l)/pdf = G2(v, l) / G1(v), computed as
// (1 + Λ(v)) / (1 + Λ(v) + Λ(l)) so that a grazing view (both G tiny) stays finite. 0 when l is at or
// below the horizon (the sample is lost: the lobe's energy that leaves below the surface).
double visibleNormalWeight(const glm::dvec3& v, const glm::dvec3& l, double alpha);

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals": a microfacet normal h drawn with density
// D_v(h) = G1(v)·max(0, v·h)·D(h) / (n·v), from two uniform numbers in [0, 1). `v` is the unit direction
// towards the viewer with v.z > 0 (a view at or below the horizon is treated as just above it). The
// result is a unit vector with h.z ≥ 0 and v·h ≥ 0; reflecting −v about it gives the light direction.
glm::dvec3 sampleVisibleNormal(const glm::dvec3& v, double alpha, double u1, double u2);

// l = reflect(−v, h) = 2(v·h)h − v.
glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h);

// The directional albedo E(μ_v, α) = ∫ f(v, l) (n·l) dω_l of the lobe with F = 1 (what a rough perfect
// mirror reflects of a uniform white surround), by deterministic quadrature over l: composite
// Gauss–Legendre in θ_l (the lobe is smooth, so this converges fast even where it is narrow) and the
// midpoint rule in φ_l (periodic). `cosThetaV` in (0, 1]; accurate to about 1e-9 for α ≥ 0.04 at the
// default resolution.
double ggxDirectionalAlbedo(double cosThetaV, double alpha, int thetaPanels = 256, int phiSteps = 512);

} // namespace speculum::render::math
