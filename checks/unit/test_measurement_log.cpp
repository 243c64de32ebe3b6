#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "MeasurementLog.h"
#include "RunLog.h"

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

// The run log goes through the same writer (StreamedFile) as the measurement
// files: its lines as they were, and a hard link refused like theirs.
TEST(RunLog, WritesItsHeaderAndEntriesFlushed) {
  const std::string path = "run_log_test.txt";
  odelab::RunLog log;
  log.setTarget(path, "test2 - Pendulum");
  EXPECT_EQ(log.write(0.25, 250, "ERP 0.2 -> 0.4"), "");
  EXPECT_EQ(log.write(1.5, 1500, "paused"), "");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "# test2 - Pendulum: inputs that changed the simulation, with their simulated time\n"
            "t=0.25 s (step 250): ERP 0.2 -> 0.4\nt=1.5 s (step 1500): paused\n");
  std::remove(path.c_str());
}

TEST(RunLog, AHardLinkIsNotWrittenThrough) {
  const std::string path = "run_log_linked.txt", victim = "run_log_victim.txt";
  std::ofstream(victim) << "precious";
  ASSERT_EQ(link(victim.c_str(), path.c_str()), 0);
  odelab::RunLog log;
  log.setTarget(path, "t");
  EXPECT_NE(log.write(0, 0, "x").find("has more than one link"), std::string::npos);
  std::ifstream in(victim);
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "precious");
  std::remove(path.c_str());
  std::remove(victim.c_str());
}
