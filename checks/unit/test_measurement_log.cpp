#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "MeasurementLog.h"

TEST(MeasurementLog, WritesHeaderRowsAndCommentsFlushedAsItGoes) {
  const std::string path = "measurement_log_test.txt";
  odelab::MeasurementLog log;
  log.open(path, "test2 - Pendulum", {{"erp", "0.4"}, {"cfm", "0"}}, {"time_s", "total_J"});
  log.row({0.0, 29.5});
  log.comment(0.5, "ERP 0.4 -> 0.5");
  log.row({1.0, 29.4});
  // Flushed: readable before close.
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "# test2 - Pendulum\n# erp: 0.4\n# cfm: 0\ntime_s\ttotal_J\n0\t29.5\n"
            "# t=0.5 s: ERP 0.4 -> 0.5\n1\t29.4\n");
  EXPECT_EQ(log.rows(), 2);
  log.close();
  std::remove(path.c_str());
}

TEST(MeasurementLog, UnwritablePathThrows) {
  odelab::MeasurementLog log;
  EXPECT_THROW(log.open("/nonexistent-folder/x.txt", "t", {}, {}), std::runtime_error);
}

TEST(MeasurementLog, JoinPath) {
  EXPECT_EQ(odelab::joinPath(".", "a.txt"), "a.txt");
  EXPECT_EQ(odelab::joinPath("out", "a.txt"), "out/a.txt");
  EXPECT_EQ(odelab::joinPath("out/", "a.txt"), "out/a.txt");
}
