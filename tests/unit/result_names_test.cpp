// Requirement (issue 10): a run removes from its folder only the files StrandFEM itself writes.
#include <gtest/gtest.h>

#include "strandfem/io/result_writer.hpp"

namespace strandfem {
namespace {

TEST(ResultNames, OnlyStrandFemResultNamesAreRemovable) {
  for (const char* name : {"history.csv", "summary.json", "summary.json.tmp", "contacts.csv", "wires.csv", "loops.csv", "deflection_curves.csv", "displacements.csv",
                           "result.pvd", "contacts.pvd", "result_00000.vtu", "result_123456.vtu", "contacts_00007.vtu",
                           "result_00001.vtu.tmp"})
    EXPECT_TRUE(is_result_file_name(name)) << name;
  for (const char* name : {"notes.txt", "result_1.vtu", "result_0000a.vtu", "my_result_00001.vtu", "result.pvd.bak",
                           "history.csv.orig", "summary.json.tmp.tmp", ".tmp", "history.tmp", "result_00001.vtk"})
    EXPECT_FALSE(is_result_file_name(name)) << name;
}

}  // namespace
}  // namespace strandfem
