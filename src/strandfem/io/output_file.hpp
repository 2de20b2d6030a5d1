// Result files written safely: whole files appear only once complete (temporary name, then rename), appended
// files are flushed and checked row by row; any write error is an OutputError naming the file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "strandfem/core/archive.hpp"

namespace strandfem {

// Results could not be written (folder not creatable, disk full, file not writable). Exit code 4 in the program.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Suffix of a whole file while it is being written.
inline constexpr const char* kPartialSuffix = ".tmp";

// A file written whole: the text goes to NAME.tmp, which is renamed to NAME (replacing an older one at once)
// only after it was written and closed without error. A reader never sees half a file.
class WholeFile {
 public:
  explicit WholeFile(std::filesystem::path path);
  WholeFile(const WholeFile&) = delete;
  WholeFile& operator=(const WholeFile&) = delete;
  ~WholeFile();  // removes NAME.tmp when commit() was not reached
  std::ostream& stream() { return out_; }
  void commit();

 private:
  std::filesystem::path path_, partial_;
  std::ofstream out_;
  bool committed_ = false;
};

// A file appended row by row (history.csv, contacts.csv, wires.csv): each row is flushed as it ends, so that a
// run stopped at any point leaves whole rows, and every flush is checked.
class AppendedFile {
 public:
  void open(const std::filesystem::path& path);  // truncates
  // Resuming a run: cuts the file back to `size` bytes (dropping rows written after the checkpoint) and appends
  // from there. OutputError when the file is missing or shorter than that.
  void resume(const std::filesystem::path& path, std::uintmax_t size);
  std::uintmax_t size() const;  // bytes written so far (every row is flushed)
  // Checkpoints: the length written so far (0 for a file this run does not write, never opened); resume_from
  // reads it back and, for a file the run writes, resumes there.
  void save_length(ArchiveWriter& out) const;
  void resume_from(ArchiveReader& in, const std::filesystem::path& path, bool written);
  bool is_open() const { return out_.is_open(); }
  std::ostream& stream() { return out_; }
  void end_row();

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

// Throws OutputError "cannot write PATH: reason" with the errno text when there is one.
[[noreturn]] void throw_output_error(const std::filesystem::path& path, const std::string& what, int error_number);

}  // namespace strandfem
