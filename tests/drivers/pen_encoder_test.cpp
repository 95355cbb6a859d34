// encode_pen_report is the decoder's inverse: on every pen layout of every shared descriptor
// (the shared corpus, when present) and of the project's generated descriptors, random samples
// encode and decode back to themselves.
#include "penshape/drivers/pen_encoder.hpp"

#include <gtest/gtest.h>

#include <random>

#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_decoder.hpp"
#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

TEST(PenEncoder, RoundTripsThroughTheDecoderOnEverySharedPenLayout) {
  std::mt19937 rng(17);
  std::size_t layouts = 0;
  auto descriptors = testing::all_shared_descriptors();
  for (auto& d : testing::generated_descriptors()) descriptors.push_back(std::move(d));
  for (const auto& d : descriptors) {
    ParsedDescriptor parsed;
    try {
      parsed = parse_report_descriptor(d.bytes);
    } catch (const DescriptorError&) {
      continue; // the descriptor tests cover parse errors
    }
    for (const PenLayout& layout : find_pen_layouts(parsed)) {
      if (layout.match_reject) continue; // told apart by what it is not: nothing to write
      ++layouts;
      const PenDecoder decoder({layout});
      for (int i = 0; i < 50; ++i) {
        PenSample s;
        s.x = std::uniform_int_distribution<std::int32_t>(0, layout.x_max())(rng);
        s.y = std::uniform_int_distribution<std::int32_t>(0, layout.y_max())(rng);
        s.pressure = layout.pressure.present() ? std::uniform_int_distribution<std::uint32_t>(
                                                     0, layout.pressure_max())(rng)
                                               : 0;
        s.tip = layout.tip.present() && (i % 3 != 0);
        s.in_range = true;
        if (layout.barrel1.present() && i % 4 == 1) s.buttons |= kBarrel1;
        PenSample back;
        const auto bytes = encode_pen_report(layout, s);
        ASSERT_EQ(decoder.decode(bytes, 1000, back), DecodeStatus::kPen) << d.source;
        EXPECT_EQ(back.x, s.x) << d.source;
        EXPECT_EQ(back.y, s.y) << d.source;
        EXPECT_EQ(back.pressure, s.pressure) << d.source;
        if (layout.tip.present()) {
          EXPECT_EQ(back.tip, s.tip) << d.source;
        }
        EXPECT_EQ(back.buttons & kBarrel1, s.buttons & kBarrel1) << d.source;
        EXPECT_EQ(back.time_us, 1000);
      }
    }
  }
  // Over a hundred pen layouts in the shared corpus; the generated descriptors have one each.
  EXPECT_GE(layouts, test::shared_path("hid") ? 100U : testing::generated_descriptors().size());
}

} // namespace
} // namespace penshape::drivers
