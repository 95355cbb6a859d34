// libFuzzer target: everything a client or a config file can hand the daemon — config text,
// DeconstructRequest and Stroke bytes — must end in a result or a named error, never a crash.
// The first byte picks the input kind; the rest is the input.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "penshape/daemon/config.hpp"
#include "penshape/daemon/proto_convert.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char* text = reinterpret_cast<const char*>(data + 1);
  const std::size_t length = size - 1;
  penshape::daemon::Limits limits;
  limits.max_vertices = 2'000; // keeps each run short; the check itself is what is fuzzed
  switch (data[0] % 3) {
    case 0:
      try {
        penshape::daemon::parse_config(std::string_view(text, length), "fuzz.conf");
      } catch (const penshape::daemon::ConfigError&) {
      }
      break;
    case 1: {
      penshape::v1::DeconstructRequest request;
      if (!request.ParseFromArray(text, static_cast<int>(length))) break;
      try {
        const auto q =
            penshape::daemon::polygon_set_from_proto(request.polygon(), "polygon", limits);
        const auto params = penshape::daemon::deconstruct_params_from_proto(request, limits);
        penshape::v1::PolygonSet back;
        penshape::daemon::to_proto(q, &back);
        (void)params;
      } catch (const penshape::daemon::FieldError&) {
      }
      break;
    }
    default: {
      penshape::v1::Stroke stroke;
      if (!stroke.ParseFromArray(text, static_cast<int>(length))) break;
      try {
        penshape::daemon::stroke_from_proto(stroke, "stroke", limits, true);
      } catch (const penshape::daemon::FieldError&) {
      }
      break;
    }
  }
  return 0;
}
