// Geometry.Recognize as a StrokeRecognizer (see daemon_recognizer.hpp).
#include "daemon_recognizer.hpp"

#include <grpcpp/client_context.h>

#include <chrono>
#include <cmath>

#include "penshape/v1/geometry.grpc.pb.h"

namespace penshape::snap {
namespace {

constexpr double kUnitsPerMm = 1000.0;
constexpr auto kCallTimeout = std::chrono::seconds(30);

ShapeClass class_of(v1::ShapeKind k) {
  switch (k) {
    case v1::SHAPE_KIND_SEGMENT:
      return ShapeClass::kSegment;
    case v1::SHAPE_KIND_POLYLINE:
      return ShapeClass::kPolyline;
    case v1::SHAPE_KIND_TRIANGLE:
      return ShapeClass::kTriangle;
    case v1::SHAPE_KIND_RECTANGLE:
      return ShapeClass::kRectangle;
    case v1::SHAPE_KIND_SQUARE:
      return ShapeClass::kSquare;
    case v1::SHAPE_KIND_DIAMOND:
      return ShapeClass::kDiamond;
    case v1::SHAPE_KIND_REGULAR_POLYGON:
      return ShapeClass::kRegularPolygon;
    case v1::SHAPE_KIND_CIRCLE:
      return ShapeClass::kCircle;
    case v1::SHAPE_KIND_ELLIPSE:
      return ShapeClass::kEllipse;
    case v1::SHAPE_KIND_ARC:
      return ShapeClass::kArc;
    case v1::SHAPE_KIND_QUADRILATERAL:
      return ShapeClass::kQuadrilateral;
    default:
      return ShapeClass::kFreeform;
  }
}

PointD scaled(const v1::Point& p, double s) { return {p.x() * s, p.y() * s}; }

// The daemon's shape in page units (s page units per mm).
Recognition from_proto(const v1::Shape& shape, double s) {
  Recognition r;
  r.shape = class_of(shape.kind());
  if (r.shape == ShapeClass::kFreeform) return r;
  ShapeParams& p = r.params;
  if (shape.has_circle()) {
    p.center = scaled(shape.circle().center(), s);
    p.radius_x = p.radius_y = shape.circle().radius() * s;
  } else if (shape.has_ellipse()) {
    p.center = scaled(shape.ellipse().center(), s);
    p.radius_x = shape.ellipse().semi_major() * s;
    p.radius_y = shape.ellipse().semi_minor() * s;
    p.rotation = shape.ellipse().rotation_rad();
  } else if (shape.has_arc()) {
    p.center = scaled(shape.arc().center(), s);
    p.radius_x = p.radius_y = shape.arc().radius() * s;
    p.start_angle = shape.arc().start_rad();
    p.sweep_angle = shape.arc().sweep_rad();
  } else {
    for (const v1::Point& v : shape.vertices().vertices()) p.vertices.push_back(scaled(v, s));
  }
  const v1::ShapeCertificate& c = shape.certificate();
  r.certificate.certified = shape.has_certificate();
  r.certificate.bound = c.hausdorff_bound().approx() * s;
  r.certificate.epsilon = c.tolerance().approx() * s;
  r.certificate.pen_radius = c.pen_radius().approx() * s;
  r.certificate.method = c.method();
  r.epsilon = r.certificate.epsilon;
  r.pen_radius = r.certificate.pen_radius;
  r.confidence = shape.confidence();
  return r;
}

} // namespace

StrokeRecognizer daemon_recognizer(std::shared_ptr<grpc::Channel> channel) {
  auto stub = std::shared_ptr<v1::Geometry::Stub>(v1::Geometry::NewStub(channel));
  return [stub](const InkStroke& stroke, const SnapSettings& settings) {
    const double s = clean_pen_radius(stroke, settings); // page units per mm
    v1::RecognizeRequest request;
    v1::Stroke* out = request.mutable_stroke();
    v1::TabletInfo* tablet = out->mutable_tablet();
    tablet->set_name("penshape snap");
    tablet->set_x_resolution(kUnitsPerMm);
    tablet->set_y_resolution(kUnitsPerMm);
    tablet->set_pressure_max(1);
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
      const double x = stroke.points[i].x / s * kUnitsPerMm,
                   y = stroke.points[i].y / s * kUnitsPerMm;
      if (!(std::abs(x) < 2e9 && std::abs(y) < 2e9)) {
        throw DaemonCallFailed("the stroke does not fit the daemon's integer samples", true);
      }
      v1::PenSample* sample = out->add_samples();
      sample->set_time_us(static_cast<std::int64_t>(i) * 1000);
      sample->set_x(static_cast<std::int32_t>(std::lround(x)));
      sample->set_y(static_cast<std::int32_t>(std::lround(y)));
      sample->set_pressure(1);
      sample->set_in_range(true);
      sample->set_tip(true);
    }
    request.mutable_settings()->set_pen_radius_mm(1.0);
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + kCallTimeout);
    v1::RecognizeResponse response;
    const grpc::Status status = stub->Recognize(&context, request, &response);
    if (!status.ok()) {
      throw DaemonCallFailed("Recognize: " + status.error_message(),
                             status.error_code() == grpc::StatusCode::UNAVAILABLE);
    }
    return from_proto(response.shape(), s);
  };
}

} // namespace penshape::snap
