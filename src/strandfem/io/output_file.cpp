#include "strandfem/io/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace strandfem {

void throw_output_error(const std::filesystem::path& path, const std::string& what, int error_number) {
  std::string message = "cannot write " + path.string() + ": " + what;
  if (error_number != 0) message += " (" + std::string(std::strerror(error_number)) + ")";
  throw OutputError(message);
}

WholeFile::WholeFile(std::filesystem::path path) : path_(std::move(path)), partial_(path_.string() + kPartialSuffix) {
  errno = 0;
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw_output_error(partial_, "cannot create the file", errno);
}

WholeFile::~WholeFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void WholeFile::commit() {
  errno = 0;
  out_.flush();
  if (!out_) throw_output_error(partial_, "write failed", errno);
  out_.close();
  if (out_.fail()) throw_output_error(partial_, "closing failed", errno);
  std::error_code error;
  std::filesystem::rename(partial_, path_, error);
  if (error) throw_output_error(path_, "renaming " + partial_.filename().string() + " failed: " + error.message(), 0);
  committed_ = true;
}

void AppendedFile::open(const std::filesystem::path& path) {
  path_ = path;
  errno = 0;
  out_.open(path, std::ios::binary | std::ios::trunc);
  if (!out_) throw_output_error(path, "cannot create the file", errno);
}

void AppendedFile::resume(const std::filesystem::path& path, std::uintmax_t size) {
  path_ = path;
  std::error_code error;
  const std::uintmax_t found = std::filesystem::file_size(path, error);
  if (error) throw_output_error(path, "cannot resume: the file is missing (" + error.message() + ")", 0);
  if (found < size)
    throw_output_error(path, "cannot resume: the file is shorter (" + std::to_string(found) + " bytes) than at the checkpoint (" +
                                 std::to_string(size) + ")", 0);
  std::filesystem::resize_file(path, size, error);
  if (error) throw_output_error(path, "cannot resume: cutting the file back failed: " + error.message(), 0);
  errno = 0;
  out_.open(path, std::ios::binary | std::ios::app);
  if (!out_) throw_output_error(path, "cannot open the file to append", errno);
}

std::uintmax_t AppendedFile::size() const {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path_, error);
  if (error) throw_output_error(path_, "cannot read the file's size: " + error.message(), 0);
  return bytes;
}

void AppendedFile::save_length(ArchiveWriter& out) const {
  out.value(static_cast<std::uint64_t>(is_open() ? size() : 0));
}

void AppendedFile::resume_from(ArchiveReader& in, const std::filesystem::path& path, bool written) {
  const auto length = in.value<std::uint64_t>();
  if (written) resume(path, length);
}

void AppendedFile::end_row() {
  errno = 0;
  out_.flush();
  if (!out_) throw_output_error(path_, "write failed", errno);
}

}  // namespace strandfem
