#include "record_command_capture.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "penshape/drivers/hid_descriptor.hpp"

namespace penshape::cli {
namespace {

std::uint16_t usb_id(std::uint32_t value, const char* field) {
  if (value > 0xffff) {
    throw std::invalid_argument(std::string("DeviceInfo.hid.") + field + " " +
                                std::to_string(value) + " is not a 16-bit id");
  }
  return static_cast<std::uint16_t>(value);
}

} // namespace

std::optional<drivers::Recording> capture_header(const v1::DeviceInfo& device) {
  if (!device.has_hid() || device.hid().report_descriptor().empty()) return std::nullopt;
  const v1::HidFacts& hid = device.hid();
  if (hid.report_descriptor().size() > drivers::kMaxDescriptorBytes) {
    throw std::invalid_argument(
        "DeviceInfo.hid.report_descriptor has " + std::to_string(hid.report_descriptor().size()) +
        " bytes, beyond the kernel's limit of " + std::to_string(drivers::kMaxDescriptorBytes));
  }
  drivers::Recording header;
  header.descriptor.assign(hid.report_descriptor().begin(), hid.report_descriptor().end());
  header.identity.name = drivers::single_line(hid.name());
  header.phys = drivers::single_line(hid.phys());
  header.identity.bus = static_cast<Bus>(usb_id(hid.bus(), "bus"));
  header.identity.vendor_id = usb_id(hid.vendor_id(), "vendor_id");
  header.identity.product_id = usb_id(hid.product_id(), "product_id");
  // The drivers' rule for files without an I: line: ids 0:0 mean unknown.
  header.has_identity = header.identity.vendor_id != 0 || header.identity.product_id != 0 ||
                        header.identity.bus != Bus::kUnknown;
  for (const v1::VendorString& s : hid.vendor_strings()) {
    if (s.index() > 255) {
      throw std::invalid_argument("DeviceInfo.hid.vendor_strings index " +
                                  std::to_string(s.index()) + " is above 255");
    }
    header.vendor_strings[static_cast<std::uint8_t>(s.index())].assign(s.data().begin(),
                                                                       s.data().end());
  }
  return header;
}

CaptureWriter::CaptureWriter(std::ostream& out, const drivers::Recording& header,
                             const std::string& comment, bool track_ends)
    : out_(out), track_ends_(track_ends) {
  std::string text;
  std::size_t begin = 0;
  while (begin <= comment.size()) {
    const std::size_t end = std::min(comment.find('\n', begin), comment.size());
    text += "# " + drivers::single_line(comment.substr(begin, end - begin)) + "\n";
    begin = end + 1;
  }
  text += drivers::hid_recorder_header(header);
  put(text);
  header_bytes_ = bytes_;
}

void CaptureWriter::put(const std::string& text) {
  out_ << text;
  bytes_ += text.size();
}

void CaptureWriter::write(std::string_view report, std::int64_t time_us) {
  if (!first_time_us_) first_time_us_ = time_us;
  // Never backwards: replay tools wait for each event's time in turn.
  last_relative_us_ = std::max(last_relative_us_, time_us - *first_time_us_);
  drivers::HidEvent event;
  event.time_us = last_relative_us_;
  event.bytes.assign(report.begin(), report.end());
  put(drivers::hid_recorder_event_line(event));
  ++reports_;
  if (track_ends_) ends_.emplace_back(time_us, Cut{bytes_, reports_});
}

CaptureWriter::Cut CaptureWriter::cut_through(std::int64_t time_us) const {
  Cut cut{header_bytes_, 0};
  for (const auto& [t, end] : ends_) {
    if (t > time_us) break;
    cut = end;
  }
  return cut;
}

void CaptureWriter::forget_before(std::int64_t time_us) {
  while (ends_.size() > 1 && ends_[1].first < time_us) ends_.pop_front();
}

} // namespace penshape::cli
