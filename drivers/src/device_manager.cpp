#include "penshape/drivers/device_manager.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace penshape::drivers {

struct DeviceManager::Device {
  AttachedDevice info;
  std::unique_ptr<ReportSource> source;
  std::unique_ptr<PenPipeline> pipeline;
  std::atomic<bool> stop{false};
  std::atomic<bool> finished{false};
  std::thread thread;
};

DeviceManager::DeviceManager(std::unique_ptr<DeviceBackend> backend, DeviceCallbacks callbacks,
                             DeviceManagerOptions options, DeviceReportCallback on_report)
    : backend_(std::move(backend)),
      callbacks_(std::move(callbacks)),
      options_(std::move(options)),
      on_report_(std::move(on_report)) {}

DeviceManager::~DeviceManager() { stop(); }

void DeviceManager::start() {
  if (backend_ == nullptr || hotplug_.joinable()) return;
  stopping_ = false;
  hotplug_ = std::thread([this] { hotplug_loop(); });
}

void DeviceManager::rescan() {
  if (backend_ != nullptr) backend_->wake();
}

void DeviceManager::stop() {
  stopping_ = true;
  if (backend_ != nullptr) backend_->wake();
  if (hotplug_.joinable()) hotplug_.join();
  std::map<DeviceId, std::unique_ptr<Device>> all;
  {
    std::lock_guard lock(mutex_);
    for (auto& [id, d] : devices_) {
      d->stop = true;
      d->source->interrupt();
    }
    all.swap(devices_);
  }
  for (auto& [id, d] : all) {
    if (d->thread.joinable()) d->thread.join();
  }
  changed_.notify_all();
}

DeviceId DeviceManager::start_reader(AttachedDevice info, const DeviceProfile& profile,
                                     std::unique_ptr<ReportSource> source) {
  auto d = std::make_unique<Device>();
  info.id = next_id_++;
  d->info = info;
  d->source = std::move(source);
  const DeviceId id = info.id;
  PenCallbacks callbacks;
  callbacks.on_sample = [this, id](const PenSample& s) {
    if (callbacks_.on_sample) callbacks_.on_sample(id, s);
  };
  callbacks.on_stroke = [this, id](Stroke&& s) {
    s.id = next_stroke_id_++;
    if (callbacks_.on_stroke) callbacks_.on_stroke(id, std::move(s));
  };
  // Only a manager asked to pass reports on adds a call per report to the read path.
  ReportCallback on_report;
  if (on_report_) {
    on_report = [this, id](std::span<const std::uint8_t> bytes, std::int64_t t) {
      on_report_(id, bytes, t);
    };
  }
  d->pipeline = std::make_unique<PenPipeline>(profile, options_.segmenter, std::move(callbacks),
                                              std::move(on_report));
  Device* raw = d.get();
  {
    std::lock_guard lock(mutex_);
    devices_.emplace(id, std::move(d));
  }
  // Listed first, announced next, read last: a callback may already call devices(), and no
  // sample can precede the attach event.
  if (callbacks_.on_attach) callbacks_.on_attach(raw->info);
  std::lock_guard lock(mutex_);
  if (devices_.count(id) == 0) return id; // stop() ran meanwhile and took the device
  // Started under the lock so stop() never sees a listed device whose thread is not set yet.
  raw->thread = std::thread([this, raw] {
    // No exception may leave a thread (it would end the process): a source or callback that
    // throws ends this device's reading as if it had gone, and the rescan retries it.
    LoopEnd end = LoopEnd::kGone;
    try {
      end = run_reader_loop(*raw->source, *raw->pipeline, raw->stop, options_.read_poll);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "penshape drivers: %s: reading stopped: %s\n", raw->info.key.c_str(),
                   e.what());
    }
    const DetachReason why = end == LoopEnd::kGone  ? DetachReason::kGone
                             : end == LoopEnd::kEnd ? DetachReason::kEnded
                                                    : DetachReason::kStopped;
    if (callbacks_.on_detach) callbacks_.on_detach(raw->info.id, why, raw->pipeline->counters());
    if (why == DetachReason::kGone) {
      std::lock_guard gone_lock(mutex_);
      gone_at_[raw->info.key] = std::chrono::steady_clock::now();
    }
    raw->finished = true;
    changed_.notify_all();
    if (backend_ != nullptr && why == DetachReason::kGone) backend_->wake(); // reap + rescan
  });
  return id;
}

DeviceId DeviceManager::attach_source(const DeviceIdentity& identity,
                                      std::span<const std::uint8_t> descriptor,
                                      const VendorStrings& vendor_strings,
                                      std::unique_ptr<ReportSource> source, std::string key) {
  Recording header;
  header.identity = identity;
  header.has_identity = identity.vendor_id != 0 || identity.product_id != 0;
  header.descriptor.assign(descriptor.begin(), descriptor.end());
  header.vendor_strings = vendor_strings;
  return attach_with_header(std::move(header), std::move(source), std::move(key));
}

DeviceProfile DeviceManager::sized(DeviceProfile profile) const {
  if (profile.size_source == SizeSource::kUnknown && options_.configured_size) {
    if (const auto size =
            options_.configured_size(profile.info.vendor_id, profile.info.product_id)) {
      apply_configured_size(profile, size->first, size->second);
    }
  }
  return profile;
}

DeviceId DeviceManager::attach_with_header(Recording header, std::unique_ptr<ReportSource> source,
                                           std::string key) {
  const DeviceProfile profile =
      sized(build_profile(header.identity, header.descriptor, header.vendor_strings));
  AttachedDevice info;
  info.key = key.empty() ? "source:" + std::to_string(next_id_.load()) : std::move(key);
  info.tablet = profile.info;
  info.protocol = profile.protocol;
  info.family = profile.family;
  info.size_source = profile.size_source;
  info.header = std::move(header);
  return start_reader(std::move(info), profile, std::move(source));
}

DeviceId DeviceManager::attach_replay(const Recording& recording, ReplaySpeed speed) {
  // Replays that ended are reaped here too: without a backend no hotplug thread does it, and a
  // daemon replaying in a loop would keep every finished replay (its reports, its thread).
  reap_finished();
  Recording header; // everything but the reports, which the source gets
  header.identity = recording.identity;
  header.has_identity = recording.has_identity;
  header.phys = recording.phys;
  header.descriptor = recording.descriptor;
  header.vendor_strings = recording.vendor_strings;
  return attach_with_header(std::move(header),
                            std::make_unique<RecordingSource>(recording.events, speed),
                            "replay:" + std::to_string(next_id_.load()));
}

void DeviceManager::reap_finished() {
  std::vector<std::unique_ptr<Device>> done;
  {
    std::lock_guard lock(mutex_);
    for (auto it = devices_.begin(); it != devices_.end();) {
      if (it->second->finished) {
        done.push_back(std::move(it->second));
        it = devices_.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (auto& d : done) {
    if (d->thread.joinable()) d->thread.join();
  }
  if (!done.empty()) changed_.notify_all();
}

void DeviceManager::scan_once() {
  std::set<std::string> attached;
  const auto now = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(mutex_);
    for (const auto& [id, d] : devices_) attached.insert(d->info.key);
    for (auto it = gone_at_.begin(); it != gone_at_.end();) {
      if (now - it->second < options_.reattach_backoff) {
        attached.insert(it->first); // vanished a moment ago: not yet
        ++it;
      } else {
        it = gone_at_.erase(it);
      }
    }
  }
  for (const DeviceCandidate& c : backend_->scan()) {
    if (stopping_) return;
    if (attached.count(c.key) != 0) continue;
    try {
      VendorStrings strings;
      const auto indexes = vendor_string_indexes(c.identity.vendor_id, c.identity.product_id);
      if (!indexes.empty()) strings = backend_->read_vendor_strings(c, indexes);
      const DeviceProfile profile = sized(build_profile(c.identity, c.descriptor, strings));
      if (!profile.has_pen()) continue;
      auto source = backend_->open(c, profile.init);
      AttachedDevice info;
      info.key = c.key;
      info.tablet = profile.info;
      info.protocol = profile.protocol;
      info.family = profile.family;
      info.size_source = profile.size_source;
      info.header.identity = c.identity;
      if (!c.hid_name.empty()) info.header.identity.name = c.hid_name;
      info.header.has_identity = true;
      info.header.phys = c.phys;
      info.header.descriptor = c.descriptor;
      info.header.vendor_strings = strings;
      start_reader(std::move(info), profile, std::move(source));
    } catch (const std::exception& e) {
      // A device we cannot use now (permissions, a half-initialised node): the next rescan or
      // hotplug event retries it.
      std::fprintf(stderr, "penshape drivers: %s: %s\n", c.key.c_str(), e.what());
    }
  }
}

void DeviceManager::hotplug_loop() {
  while (!stopping_) {
    // A failed scan (enumeration, sysfs) is retried at the next change or rescan; it must never
    // leave the thread.
    try {
      reap_finished();
      scan_once();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "penshape drivers: device scan failed: %s\n", e.what());
    }
    if (stopping_) break;
    backend_->wait_for_change(options_.rescan_interval);
  }
}

std::vector<AttachedDevice> DeviceManager::devices() const {
  std::lock_guard lock(mutex_);
  std::vector<AttachedDevice> out;
  for (const auto& [id, d] : devices_) {
    if (!d->finished) out.push_back(d->info);
  }
  return out;
}

bool DeviceManager::wait_until_idle(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] {
    return std::all_of(devices_.begin(), devices_.end(),
                       [](const auto& kv) { return kv.second->finished.load(); });
  });
}

} // namespace penshape::drivers
