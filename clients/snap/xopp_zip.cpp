// libzip on buffers (see xopp_zip.hpp): a zip_source over the bytes, opened as an archive; on
// write the source is kept past zip_close, which leaves the new archive in it.
#include "xopp_zip.hpp"

#include <zip.h>

#include <memory>
#include <stdexcept>

#include "snap_error.hpp"

namespace penshape::snap {
namespace {

struct ArchiveCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct FileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};
struct SourceFreer {
  void operator()(zip_source_t* s) const { zip_source_free(s); }
};
using Archive = std::unique_ptr<zip_t, ArchiveCloser>;
using Source = std::unique_ptr<zip_source_t, SourceFreer>;

// The archive over a source the caller keeps (zip_source_keep: the archive holds a reference).
Archive open_archive(zip_source_t* source, int flags) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_keep(source);
  zip_t* z = zip_open_from_source(source, flags, &error);
  if (z == nullptr) {
    zip_source_free(source);
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw SnapInputError("the file is no readable zip: " + why);
  }
  zip_error_fini(&error);
  return Archive(z);
}

Source buffer_source(const void* data, std::size_t size) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* s = zip_source_buffer_create(data, size, 0, &error);
  zip_error_fini(&error);
  if (s == nullptr) throw std::runtime_error("libzip: cannot make a buffer source");
  return Source(s);
}

// All of a source's bytes (the archive zip_close wrote into it).
std::string source_bytes(zip_source_t* s) {
  if (zip_source_open(s) != 0) throw std::runtime_error("libzip: cannot reopen the new archive");
  std::string out;
  char buf[1 << 16];
  for (zip_int64_t n = zip_source_read(s, buf, sizeof buf); n > 0;
       n = zip_source_read(s, buf, sizeof buf)) {
    out.append(buf, static_cast<std::size_t>(n));
  }
  zip_source_close(s);
  return out;
}

} // namespace

bool looks_zipped(std::string_view b) { return b.size() >= 4 && b.substr(0, 4) == "PK\x03\x04"; }

std::string zip_entry(std::string_view zip, const char* name, std::size_t limit) {
  const Source source = buffer_source(zip.data(), zip.size());
  const Archive archive = open_archive(source.get(), ZIP_RDONLY);
  const std::unique_ptr<zip_file_t, FileCloser> file(zip_fopen(archive.get(), name, 0));
  if (!file) {
    throw SnapInputError(std::string("the zip has no readable ") + name + ": " +
                         zip_strerror(archive.get()));
  }
  std::string out;
  char buf[1 << 16];
  zip_int64_t n = 0;
  while ((n = zip_fread(file.get(), buf, sizeof buf)) > 0) {
    if (out.size() + static_cast<std::size_t>(n) > limit) {
      throw SnapInputError(std::string("the zip's ") + name + " expands beyond " +
                           std::to_string(limit) + " bytes");
    }
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (n < 0) {
    throw SnapInputError(std::string("the zip's ") + name +
                         " is corrupt: " + zip_file_strerror(file.get()));
  }
  return out;
}

std::string zip_with_entry(std::string_view zip, const char* name, const std::string& content) {
  // A copy the archive may rewrite in place.
  const Source target = buffer_source(zip.data(), zip.size());
  Archive archive = open_archive(target.get(), 0);
  const zip_int64_t index = zip_name_locate(archive.get(), name, 0);
  zip_source_t* entry = zip_source_buffer(archive.get(), content.data(), content.size(), 0);
  if (index < 0 || entry == nullptr ||
      zip_file_replace(archive.get(), static_cast<zip_uint64_t>(index), entry, 0) != 0) {
    if (entry != nullptr) zip_source_free(entry);
    throw std::runtime_error(std::string("libzip: cannot replace ") + name);
  }
  if (zip_close(archive.get()) != 0) {
    throw std::runtime_error(std::string("libzip: cannot write the archive: ") +
                             zip_strerror(archive.get()));
  }
  (void)archive.release(); // closed
  return source_bytes(target.get());
}

} // namespace penshape::snap
