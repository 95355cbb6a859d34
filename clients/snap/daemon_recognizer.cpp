// Geometry.Recognize as a PageRecognizer (see daemon_recognizer.hpp).
#include "daemon_recognizer.hpp"

#include <grpcpp/client_context.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "penshape/proto/shape_kind.hpp"
#include "penshape/v1/geometry.grpc.pb.h"

namespace penshape::snap {
namespace {

constexpr double kUnitsPerMm = 1000.0;
constexpr auto kCallTimeout = std::chrono::seconds(30);

PointD scaled(const v1::Point& p, double s) { return {p.x() * s, p.y() * s}; }

// The daemon's shape in page units (s page units per mm).
Recognition from_proto(const v1::Shape& shape, double s) {
  Recognition r;
  r.shape = proto::from_proto(shape.kind()).value_or(ShapeClass::kFreeform);
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
  } else if (shape.has_arrow()) {
    const v1::ArrowParams& a = shape.arrow();
    p.vertices = {scaled(a.tail(), s), scaled(a.tip(), s)};
    for (const v1::Point& v : a.barbs()) p.vertices.push_back(scaled(v, s));
    for (const v1::Point& v : a.tail_barbs()) p.vertices.push_back(scaled(v, s));
    p.head_angle = a.head_angle_rad();
    p.shaft_bulge = a.shaft_bulge() * s;
    for (const v1::Point& v : a.shaft_bends()) p.shaft_bends.push_back(scaled(v, s));
    if (a.has_shaft_end()) p.shaft_end = scaled(a.shaft_end(), s);
  } else {
    for (const v1::Point& v : shape.vertices().vertices()) p.vertices.push_back(scaled(v, s));
  }
  const v1::ShapeCertificate& c = shape.certificate();
  // A curved shaft comes without its path (Recognition::clean), which snap would draw straight:
  // not what was certified, so it is not written.
  r.certificate.certified = shape.has_certificate() && p.shaft_bulge == 0;
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

namespace {

constexpr std::size_t kStrokesPerCall = 64; // RecognizeRequest.strokes' limit

void add_stroke(const InkStroke& stroke, double start, double s, v1::Stroke* out) {
  v1::TabletInfo* tablet = out->mutable_tablet();
  tablet->set_name("penshape snap");
  tablet->set_x_resolution(kUnitsPerMm);
  tablet->set_y_resolution(kUnitsPerMm);
  tablet->set_pressure_max(1);
  for (const StrokePoint& q : timed_samples(stroke, start)) {
    const double x = q.x / s * kUnitsPerMm, y = q.y / s * kUnitsPerMm;
    if (!(std::abs(x) < 2e9 && std::abs(y) < 2e9)) {
      throw DaemonCallFailed(
          stroke.where + ": the stroke does not fit the daemon's integer samples", true);
    }
    v1::PenSample* sample = out->add_samples();
    sample->set_time_us(std::llround(q.t * 1e6));
    sample->set_x(static_cast<std::int32_t>(std::lround(x)));
    sample->set_y(static_cast<std::int32_t>(std::lround(y)));
    sample->set_pressure(1);
    sample->set_in_range(true);
    sample->set_tip(true);
  }
}

// One call for page[first, first + count): their answers, stroke indices into the page.
std::vector<StrokeSnap> recognize_batch(v1::Geometry::Stub& stub,
                                        const std::vector<InkStroke>& page, std::size_t first,
                                        std::size_t count, const SnapSettings& settings) {
  std::vector<double> radii;
  for (std::size_t i = first; i < first + count; ++i) {
    radii.push_back(clean_pen_radius(page[i], settings));
  }
  std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                   radii.end());
  const double s = radii[radii.size() / 2]; // page units per mm
  v1::RecognizeRequest request;
  double start = 0;
  for (std::size_t i = first; i < first + count; ++i) {
    add_stroke(page[i], start, s, request.add_strokes());
    start += 0.01 * static_cast<double>(page[i].points.size()) + 0.1; // as timed_samples
  }
  request.mutable_settings()->set_pen_radius_mm(1.0);
  request.mutable_grouping()->set_disabled(!settings.group);
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + kCallTimeout);
  v1::RecognizeResponse response;
  const grpc::Status status = stub.Recognize(&context, request, &response);
  if (!status.ok()) {
    throw DaemonCallFailed("Recognize: " + status.error_message(),
                           status.error_code() == grpc::StatusCode::UNAVAILABLE);
  }
  std::vector<StrokeSnap> out;
  for (const v1::RecognizedGroup& g : response.groups()) {
    StrokeSnap snap;
    for (const std::uint32_t k : g.strokes()) {
      if (k >= count) {
        throw DaemonCallFailed(
            "Recognize: a group names stroke " + std::to_string(k) + " of " + std::to_string(count),
            false);
      }
      snap.strokes.push_back(first + k);
    }
    if (snap.strokes.empty()) continue;
    snap.recognition = from_proto(g.shape(), s);
    snap.tidy.assign(g.tidy().begin(), g.tidy().end());
    out.push_back(std::move(snap));
  }
  return out;
}

} // namespace

PageRecognizer daemon_recognizer(const std::shared_ptr<grpc::Channel>& channel) {
  auto stub = std::shared_ptr<v1::Geometry::Stub>(v1::Geometry::NewStub(channel));
  return [stub](const std::vector<InkStroke>& page, const SnapSettings& settings) {
    std::vector<StrokeSnap> out;
    for (std::size_t first = 0; first < page.size(); first += kStrokesPerCall) {
      const std::size_t count = std::min(kStrokesPerCall, page.size() - first);
      for (StrokeSnap& snap : recognize_batch(*stub, page, first, count, settings)) {
        out.push_back(std::move(snap));
      }
    }
    return out;
  };
}

} // namespace penshape::snap
