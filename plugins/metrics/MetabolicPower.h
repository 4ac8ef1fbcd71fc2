#pragma once
// Metabolic power of running with accelerations, after di Prampero et al. (2005) "Sprint running: a new
// energetic approach", J Exp Biol 208:2809–2816, in the form Osgnach et al. (2010) "Energy cost and
// metabolic power in elite soccer", Med Sci Sports Exerc 42(1):170–178, use for match analysis:
//
//   accelerated running on flat ground ≙ uphill running at constant speed on the equivalent slope
//     ES = tan(90° − atan(g / a_f)) = a_f / g                                      (Osgnach eq. 2)
//   with the equivalent body mass (ratio of the resultant of a_f and g to g)
//     EM = √(a_f² / g² + 1)                                                       (Osgnach eq. 3)
//   the energy cost of running on that slope (Minetti et al. 2002), scaled by EM and the terrain factor
//     EC = (155.4 ES⁵ − 30.4 ES⁴ − 43.3 ES³ + 46.3 ES² + 19.5 ES + 3.6) · EM · KT   [J kg⁻¹ m⁻¹]  (eq. 4)
//   and the metabolic power P = EC · v  [W kg⁻¹]                                   (eq. 5)
// KT = 1.29 for grass (Osgnach 2010, after Pugh 1971). At constant speed EC = 3.6 · KT = 4.644 J/kg/m.
// The polynomial was fitted for slopes of −0.45 … +0.45 (Minetti 2002); outside that range the values are
// extrapolations (a_f beyond ±4.4 m/s²), which the docs state.
namespace athlos::metrics {

struct MetabolicParams {
    double terrainFactor = 1.29;  // KT, grass (Osgnach 2010)
    double gravity = 9.81;        // m/s²
};

// Energy cost EC (J kg⁻¹ m⁻¹) at forward acceleration a_f (m/s²).
double energyCost(double forwardAccel, const MetabolicParams& params = {});
// Metabolic power P = EC · v (W kg⁻¹) at speed v (m/s) and forward acceleration a_f (m/s²).
double metabolicPower(double speed, double forwardAccel, const MetabolicParams& params = {});

}  // namespace athlos::metrics
