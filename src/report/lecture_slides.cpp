/// The lecture slide by slide (LECTURE.md: what each slide shows and the
/// formula it states), each with the figure or table of the report that
/// reproduces it. The titles are LECTURE.md's words; the page's index lists
/// them, and each section shows the formulas of its slides.
#include <algorithm>

#include "sections.hpp"

namespace stratum::report {

const std::vector<LectureSlide>& lecture_slides() {
  static const std::vector<LectureSlide> slides{
      {"§1", "The camera integral: pixel area, lens and shutter time",
       "R = ∫_T ∫_Ω ∫_A L(x, ω, t) P(x) S(t) cos θ dA dω dt", "camera", ""},
      {"§1", "Sampling the lens: depth of field (Mitchell 1991)", "", "camera", "figure-camera-depth-of-field"},
      {"§1", "Sampling time: motion blur (Cook, Porter, Carpenter 1984)", "", "camera", "figure-camera-motion-blur"},
      {"§2", "Variance, and the variance of a mean", "V[Y] = E[(Y − E[Y])²] = E[Y²] − E[Y]²;  V[(1/N) Σ Y_i] = V[Y]/N",
       "variance", ""},
      {"§2", "Soft shadows: 1 shadow ray per eye ray versus 16", "", "variance", "figure-variance-shadow-rays"},
      {"§2", "Efficiency: twice the variance needs twice the samples, twice the cost twice the time",
       "efficiency ∝ 1 / (V × T)", "variance", "table-shadow-rays"},
      {"§3", "Importance sampling: draw X ~ p and weight by 1/p; zero variance when p ∝ f",
       "Y = f(X)/p(X),  E[Y] = ∫ f;  p = f/∫f ⇒ V[Y] = 0", "importance", "figure-importance-zero-variance"},
      {"§3", "Examples: an area light sampled by area versus by projected solid angle, 4 eye rays × 100 shadow rays",
       "p_A = 1/A;  p_σ⊥(ω) = 1/Ω⊥ (projected solid angle)", "importance", "figure-importance-light-strategy"},
      {"§3", "Irradiance with cosine-weighted directions", "E = ∫_H² L(ω) cos θ dω,  p(ω) = cos θ / π", "importance",
       "figure-importance-hemisphere"},
      {"§4", "Stratified sampling: the variance of strata", "F_N = (1/N) Σ F_i,  V[F_N] = (1/N²) Σ V[F_i]",
       "stratification", "table-jittered-edge"},
      {"§4", "An edge crossing a pixel: only the √N strata it crosses contribute",
       "V ∝ √N / N² = N^−1.5 (jittered) against N^−1 (random)", "stratification", "figure-stratification-convergence"},
      {"§5", "The equi-areal polar map", "θ = 2πU₁,  r = √U₂", "disk-maps", "figure-disk-maps-maps"},
      {"§5", "Shirley's concentric map: concentric squares to concentric circles", "r = U₁,  θ = (π/4)(U₂/U₁)",
       "disk-maps", "figure-disk-maps-maps"},
      {"§6", "High dimensions: product rules against Monte Carlo",
       "product rule error ∝ N^(−r/d) (midpoint: r = 2);  Monte Carlo RMSE ∝ N^(−1/2) for every d", "dimension",
       "figure-dimension-errors"},
      {"§7", "Latin squares: each symbol once in every row and column", "", "block-designs",
       "figure-block-designs-squares"},
      {"§7", "N-rooks: one sample per row and column, n samples instead of n²",
       "x_i = (π_x(i) + U)/n,  y_i = (π_y(i) + U′)/n", "block-designs", "figure-block-designs-patterns"},
      {"§7", "N-queens and multi-jittered patterns", "", "block-designs", "table-stratification-counts"},
      {"§8", "Space-time patterns: complete in space, incomplete in time", "", "space-time",
       "figure-space-time-motion-blur"},
      {"§8", "Cook's pattern and a pan-diagonal magic square", "magic sum m(m² − 1)/2 = 30 for m = 4", "space-time",
       "figure-space-time-slot-tables"},
      {"§8", "Where the error goes: blue noise across the screen and across frames",
       "P(f) = |DFT(render − reference)|² / (N σ²) (white noise: 1)", "space-time",
       "figure-space-time-screen-space-error"},
      {"§9", "Complete (4 eye rays × 16 shadow rays) versus incomplete (64 × 1) path tracing", "4 × 16 = 64 × 1",
       "path-tracing", "figure-path-tracing-complete-incomplete"},
      {"§10", "Discrepancy of a box", "Δ(x, y) = n(x, y)/N − xy,  D_N = max |Δ|", "discrepancy",
       "figure-discrepancy-delta"},
      {"§10", "Koksma–Hlawka", "|(1/N) Σ f(X_i) − ∫ f| ≤ V(f) D_N", "discrepancy", "table-koksma-hlawka"},
      {"§10", "Edge discrepancy, and SGI's 8×8 subpixel grid with 1, 2, 4 or 8 samples",
       "D_E = sup over half-planes h of |n(h)/N − area(h)|", "edge-discrepancy",
       "figure-edge-discrepancy-grid-patterns"},
      {"§11", "The radical inverse", "i = Σ d_k b^k ⇒ φ_b(i) = Σ d_k b^(−k−1)", "qmc", "table-radical-inverse"},
      {"§11", "Hammersley and Halton points",
       "Hammersley (i/N, φ₂(i), φ₃(i), …): D_N = O(log^(d−1) N / N);  Halton (φ₂(i), φ₃(i), …): O(log^d N / N)", "qmc",
       "figure-qmc-star-vs-n"},
      {"§12", "Comparing patterns: Mitchell's (1992) discrepancy of random edges",
       "random: RMS edge discrepancy ∝ N^(−1/2)", "patterns", "table-mitchell-1992"},
      {"§12", "The patterns' spectra", "", "patterns", "figure-patterns-spectra"},
      {"§13", "Four views of integration: signal processing, statistical sampling, quasi-Monte Carlo, quadrature",
       "spectrum P(f);  variance V/N;  discrepancy D_N;  quadrature error", "four-views", "figure-four-views-ranks"},
  };
  return slides;
}

std::string figure_anchor(const Figure& figure) {
  std::string stem = figure.file.substr(figure.file.find_last_of('/') + 1);
  stem = stem.substr(0, stem.rfind('.'));
  return "figure-" + stem;
}

std::vector<SlideLocation> locate_slides(const std::vector<Section>& sections) {
  std::vector<SlideLocation> located;
  for (const LectureSlide& slide : lecture_slides()) {
    SlideLocation at{&slide};
    for (const Section& section : sections)
      if (section.id == slide.section) at.section = &section;
    if (at.section) {
      const auto& figures = at.section->figures;
      const auto& tables = at.section->tables;
      at.found = slide.anchor.empty() ||
                 std::any_of(figures.begin(), figures.end(),
                             [&](const Figure& figure) { return figure_anchor(figure) == slide.anchor; }) ||
                 std::any_of(tables.begin(), tables.end(), [&](const Table& table) {
                   return !table.id.empty() && "table-" + table.id == slide.anchor;
                 });
    }
    located.push_back(at);
  }
  return located;
}

}  // namespace stratum::report
