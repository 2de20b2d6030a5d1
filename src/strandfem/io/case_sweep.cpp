#include "strandfem/io/case_sweep.hpp"

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/case_variant.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/io/result_writer.hpp"
#include "strandfem/post/run_report.hpp"
#include "strandfem/solver/process_queue.hpp"

namespace strandfem {
namespace {

namespace fs = std::filesystem;

// --set KEY=VALUE settings, checked: one each, none the varied key.
std::vector<std::pair<std::string, std::string>> fixed_settings(const SweepDefinition& sweep) {
  std::vector<std::pair<std::string, std::string>> settings;
  for (const std::string& setting : sweep.settings) {
    const auto equals = setting.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == setting.size())
      throw CaseError("sweep --set: expected KEY=VALUE (e.g. contact.friction_direction=slave_wire), got '" + setting + "'");
    const std::string key = setting.substr(0, equals);
    if (key == sweep.key) throw CaseError("sweep --set " + key + ": the key is already varied by --key");
    for (const auto& earlier : settings)
      if (earlier.first == key) throw CaseError("sweep --set " + key + ": given twice");
    settings.emplace_back(key, setting.substr(equals + 1));
  }
  return settings;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot read the case file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The variants, their case files written into output_dir/cases (by rank 0) where the sweep sets keys.
std::vector<SweepVariant> sweep_variants(const SweepDefinition& sweep, bool write_files) {
  const auto settings = fixed_settings(sweep);
  const auto write_variant = [&](SweepVariant& v, const std::string& source, std::string text, std::string what) {
    for (const auto& [key, value] : settings) {
      text = set_case_key(text, key, value);
      what += (what.empty() ? " with " : ", ") + key + " = " + value;
    }
    v.case_file = (fs::path(sweep.output_dir) / "cases" / (v.name + ".yaml")).string();
    if (!write_files) return;
    fs::create_directories(fs::path(sweep.output_dir) / "cases");
    std::ofstream out(v.case_file);
    out << "# " << source << what << " (strandfem sweep)\n" << text;
    if (!out) throw OutputError("cannot write " + v.case_file);
  };
  std::vector<SweepVariant> variants;
  if (!sweep.key.empty()) {
    if (sweep.cases.size() != 1) throw CaseError("sweep --key varies one case, got " + std::to_string(sweep.cases.size()));
    if (sweep.values.empty()) throw CaseError("sweep --key " + sweep.key + ": expected --values v1,v2,...");
    const std::string text = read_text(sweep.cases[0]);
    for (const std::string& value : sweep.values) {
      SweepVariant v{variant_folder_name(sweep.key, value), value, ""};
      write_variant(v, sweep.cases[0], set_case_key(text, sweep.key, value), " with " + sweep.key + " = " + value);
      variants.push_back(v);
    }
  } else {
    if (!sweep.values.empty()) throw CaseError("sweep --values needs --key");
    for (const std::string& c : sweep.cases) {
      SweepVariant v{fs::path(c).stem().string(), "", c};
      for (const SweepVariant& other : variants)
        if (other.name == v.name) v.name += "_" + std::to_string(variants.size() + 1);
      if (!settings.empty()) write_variant(v, c, read_text(c), "");
      variants.push_back(v);
    }
  }
  return variants;
}

void write_table(const SweepDefinition& sweep, const std::vector<SweepVariant>& variants) {
  const std::string table = (fs::path(sweep.output_dir) / "sweep.csv").string();
  std::ofstream csv(table);
  csv << "variant,key,value,case_file,results,exit_code," << sweep_result_header() << "\n";
  for (const SweepVariant& v : variants)
    csv << v.name << "," << sweep.key << "," << v.value << "," << v.case_file << "," << v.name << "," << v.exit_code << ","
        << sweep_result_fields(read_summary(fs::path(sweep.output_dir) / v.name)) << "\n";
  if (!csv) throw OutputError("cannot write " + table);
}

}  // namespace

std::vector<SweepVariant> run_sweep(const SweepDefinition& sweep, const std::function<int(const SweepVariant&)>& run_variant,
                                    const std::function<void(const std::string&)>& progress) {
  const int rank = process_rank();
  std::vector<SweepVariant> variants = sweep_variants(sweep, rank == 0);
  ProcessQueue queue(static_cast<int>(variants.size()));  // after rank 0 wrote the case files
  for (const SweepVariant& v : variants) load_case(v.case_file, sweep.catalogue);  // bad input stops the sweep before it runs
  const std::string who = queue.processes() > 1 ? "sweep (process " + std::to_string(rank) + "): " : "sweep: ";
  std::vector<int> exit_codes(variants.size(), std::numeric_limits<int>::min());
  for (int i = queue.next(); i >= 0; i = queue.next()) {
    progress(who + variants[i].name);
    exit_codes[i] = run_variant(variants[i]);
    progress(who + variants[i].name + (exit_codes[i] == 0 ? " done" : " failed, exit code " + std::to_string(exit_codes[i])));
  }
  exit_codes = queue.largest(exit_codes);
  for (std::size_t i = 0; i < variants.size(); ++i) variants[i].exit_code = exit_codes[i];
  if (rank == 0) write_table(sweep, variants);
  return variants;
}

int sweep_exit_code(const std::vector<SweepVariant>& variants) {
  for (const SweepVariant& v : variants)
    if (v.exit_code != 0) return v.exit_code;
  return 0;
}

}  // namespace strandfem
