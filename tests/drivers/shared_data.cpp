#include "shared_data.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "descriptor_gen.hpp"
#include "penshape/drivers/recording.hpp"

namespace penshape::drivers::testing {
namespace {

std::uint16_t hex16(const std::string& s) {
  return static_cast<std::uint16_t>(std::stoul(s, nullptr, 16));
}

// The converted collections hold several devices per file (and, per their README, a few
// upstream lines with two bytes run together, e.g. "7501"): read each R: line on its own,
// splitting such tokens, and check the declared length.
void read_collection(const std::filesystem::path& file, const std::string& rel,
                     std::vector<NamedDescriptor>& out) {
  std::ifstream in(file);
  std::string line;
  std::uint16_t vid = 0, pid = 0;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "I:") {
      std::string bus, v, p;
      ls >> bus >> v >> p;
      vid = hex16(v);
      pid = hex16(p);
    } else if (tag == "N:") {
      vid = pid = 0;
    } else if (tag == "R:") {
      std::size_t n = 0;
      ls >> n;
      std::string tok, hex;
      while (ls >> tok) {
        for (char c : tok) {
          if (std::isxdigit(static_cast<unsigned char>(c))) hex += c;
        }
      }
      NamedDescriptor d;
      d.source = rel + ":" + std::to_string(line_no);
      d.vendor_id = vid;
      d.product_id = pid;
      for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
        d.bytes.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
      }
      if (d.bytes.size() != n) throw std::runtime_error(d.source + ": length mismatch");
      out.push_back(std::move(d));
    }
  }
}

} // namespace

std::vector<NamedDescriptor> all_shared_descriptors() {
  std::vector<NamedDescriptor> out;
  const auto hid = hid_dir();
  if (!hid) return out;
  const auto whd = *hid / "wacom-hid-descriptors";
  std::vector<std::filesystem::path> bins;
  for (const auto& e : std::filesystem::recursive_directory_iterator(whd)) {
    if (e.is_regular_file() && e.path().string().ends_with(".hid.bin")) bins.push_back(e.path());
  }
  std::sort(bins.begin(), bins.end());
  for (const auto& p : bins) {
    NamedDescriptor d;
    d.source = std::filesystem::relative(p, *hid).string();
    // File names are <bus>:<VID>:<PID>.<n>.hid.bin
    const std::string name = p.filename().string();
    d.vendor_id = hex16(name.substr(5, 4));
    d.product_id = hex16(name.substr(10, 4));
    const std::string bytes = read_file(p);
    d.bytes.assign(bytes.begin(), bytes.end());
    out.push_back(std::move(d));
  }
  read_collection(*hid / "hid-tools-tests/tablet_rdescs.hidrec.txt",
                  "hid-tools-tests/tablet_rdescs.hidrec.txt", out);
  read_collection(*hid / "udev-hid-bpf/huion_xppen_rdescs.hidrec.txt",
                  "udev-hid-bpf/huion_xppen_rdescs.hidrec.txt", out);
  return out;
}

std::vector<NamedDescriptor> generated_descriptors() {
  std::vector<NamedDescriptor> out;
  for (const auto& spec : gen::pen_descriptor_specs())
    out.push_back({"generated/" + spec.name, 0x1209, 0x7e50, gen::pen_descriptor(spec)});
  return out;
}

} // namespace penshape::drivers::testing
