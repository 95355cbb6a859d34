// A tablet's init reports: sent in order, and a refusal (a device that will not switch to its
// vendor mode) stops the sequence and is reported; the caller (open_hidraw) keeps the device.
#include <gtest/gtest.h>

#include <vector>

#include "init_reports.hpp"

namespace penshape::drivers {
namespace {

InitStep report(InitStep::Kind kind, std::uint8_t id) { return {kind, {id, 0x01, 0x02}, 0}; }

TEST(InitReports, SentInOrderSkippingStringDescriptors) {
  const std::vector<InitStep> init = {report(InitStep::Kind::kOutputReport, 2),
                                      {InitStep::Kind::kStringDescriptor, {}, 200},
                                      report(InitStep::Kind::kFeatureReport, 3)};
  std::vector<std::uint8_t> sent;
  EXPECT_TRUE(send_init_reports("fake", init, [&](const InitStep& s) {
    sent.push_back(s.bytes.front());
    return static_cast<int>(s.bytes.size());
  }));
  EXPECT_EQ(sent, (std::vector<std::uint8_t>{2, 3}));
}

TEST(InitReports, ARefusalStopsTheSequence) {
  const std::vector<InitStep> init = {report(InitStep::Kind::kFeatureReport, 2),
                                      report(InitStep::Kind::kFeatureReport, 3),
                                      report(InitStep::Kind::kOutputReport, 4)};
  int calls = 0;
  EXPECT_FALSE(send_init_reports("fake", init, [&](const InitStep& s) {
    ++calls;
    return s.bytes.front() == 3 ? -1 : 3;
  }));
  EXPECT_EQ(calls, 2); // the third report is never sent after the refusal
}

} // namespace
} // namespace penshape::drivers
