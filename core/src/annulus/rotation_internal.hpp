#pragma once
// Shared pieces of the rotation searches (see rotation.hpp for the methods and their bounds).
#include <vector>

#include "penshape/core/annulus/rotation.hpp"

namespace penshape::annulus::detail {

// Method 1: rotation diagrams, convex template, linearized outer offset.
MaxCoverResult max_cover_rotation_diagram(const TemplatePolygon& p, double delta,
                                          const std::vector<PointD>& points);
DecisionResult decide_rotation_diagram(const TemplatePolygon& p, double delta,
                                       const std::vector<PointD>& points);
MinWidthResult min_width_rotation_diagram(const TemplatePolygon& p,
                                          const std::vector<PointD>& points,
                                          const MinWidthOptions& options);

// Method 2: branch and bound over the angle with the translation solvers.
DecisionResult decide_rotation_angles(const TemplatePolygon& p, OuterOffset outer, double delta,
                                      const std::vector<PointD>& points,
                                      const RotationOptions& options);
MinWidthResult min_width_rotation_angles(const TemplatePolygon& p, OuterOffset outer,
                                         const std::vector<PointD>& points,
                                         const MinWidthOptions& options,
                                         const RotationOptions& rotation);
MaxCoverResult max_cover_rotation_angles(const TemplatePolygon& p, OuterOffset outer, double delta,
                                         const std::vector<PointD>& points,
                                         const RotationOptions& options);

// Method 3: branch and bound over (tx, ty, theta) cells.
MaxCoverResult max_cover_rotation_cells(const TemplatePolygon& p, OuterOffset outer, double delta,
                                        const std::vector<PointD>& points,
                                        const RotationOptions& options);
DecisionResult decide_rotation_cells(const TemplatePolygon& p, OuterOffset outer, double delta,
                                     const std::vector<PointD>& points,
                                     const RotationOptions& options);
MinWidthResult min_width_rotation_cells(const TemplatePolygon& p, OuterOffset outer,
                                        const std::vector<PointD>& points,
                                        const MinWidthOptions& options,
                                        const RotationOptions& rotation);

// Points rotated by -theta about their centroid (the frame of methods 2 and 3).
class RotatedFrame {
 public:
  explicit RotatedFrame(const std::vector<PointD>& points);

  // A sample angle: u = tan(theta / 2) is the exact rotation of the placements built from it;
  // (c, s) its cosine and sine in doubles; theta = 2 atan(u).
  struct Angle {
    double u, theta, c, s;
  };
  static Angle angle(double theta);

  [[nodiscard]] std::vector<PointD> rotated(const Angle& a) const;
  // The placement (theta, centre - R(theta)(centre - t)) of a translation t of the rotated points.
  [[nodiscard]] Placement placement(const Angle& a, PointD t) const;
  [[nodiscard]] PointD centre() const { return centre_; }
  [[nodiscard]] double rho() const { return rho_; } // max |q - centre|, rounded up
  [[nodiscard]] double rho_of(std::size_t i) const { return rho_i_[i]; }
  // Bound on the rounding error of a rotated point (and of a measure computed from it).
  [[nodiscard]] double slack(const TemplatePolygon& p, double delta) const;

 private:
  const std::vector<PointD>& points_;
  PointD centre_{};
  double rho_ = 0.0;
  double magnitude_ = 0.0;
  std::vector<double> rho_i_;
};

// Reach of a sample angle over [lo, hi]: the largest distance to an end, rounded up.
double angle_reach(const RotatedFrame::Angle& a, double lo, double hi);

} // namespace penshape::annulus::detail
