// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace design` end to end: exit statuses (2 on bad input, 130 after
// Ctrl-C, 128 + signal after SIGTERM or SIGHUP, with the best design so far
// written; 130 and nothing written after a Ctrl-C before the first
// iteration), --designs K with its contact sheet, stale outputs of an earlier
// run, and no progress output when stderr is not a terminal.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "tests/support/scratch.h"

namespace {

namespace fs = std::filesystem;
const std::string kBin = HRSPACE_BIN;
const std::string kBedroom = std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json";

int run(const std::string& args, std::string* err = nullptr) {
  const std::string errfile = hrs::test_support::scratch_path("cli_test.err").string();
  const int status = std::system((kBin + " " + args + " >/dev/null 2>" + errfile).c_str());
  if (err) {
    std::ifstream in(errfile);
    std::stringstream ss;
    ss << in.rdbuf();
    *err = ss.str();
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(DesignCli, BadInputExitsTwoWithOneLine) {
  const std::string out = hrs::test_support::scratch_path("cli_bad").string();
  std::string err;
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --planner fast", &err), 2);
  EXPECT_NE(err.find("--planner"), std::string::npos);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);  // one line
  EXPECT_EQ(run("design " + kBedroom), 2);                 // no --out
  EXPECT_EQ(run("design /nonexistent.json --out " + out), 2);
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --iterations x"), 2);
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --designs 0"), 2);
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --restarts 0", &err), 2);
  EXPECT_NE(err.find("--restarts"), std::string::npos);
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --restarts 101"), 2);
  EXPECT_EQ(run("design " + kBedroom + " --out " + out + " --bogus 1"), 2);
  EXPECT_EQ(run("design --help"), 0);
}

TEST(DesignCli, SeveralDesignsGoToNumberedDirectoriesWithAContactSheet) {
  const fs::path out = hrs::test_support::scratch_path("cli_multi");
  fs::remove_all(out);
  std::string err;
  ASSERT_EQ(
      run("design " + kBedroom + " --out " + out.string() + " --designs 2 --seed 5 --iterations 3",
          &err),
      0);
  EXPECT_EQ(err, "");  // stderr is a file, not a terminal: no progress bar
  for (const char* d : {"1", "2"})
    for (const char* f : {"layout.json", "tours.json", "design.svg", "report.json"})
      EXPECT_TRUE(fs::exists(out / d / f)) << d << "/" << f;
  EXPECT_TRUE(fs::exists(out / "contact_sheet.svg"));
  std::ifstream r2(out / "2" / "report.json");
  const auto report = nlohmann::json::parse(r2);
  EXPECT_EQ(report["seed"], 6);
  EXPECT_EQ(report["iterations_run"], 3);
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(DesignCli, RestartsKeepTheCheapestChainAndItsSeedRepeatsItAlone) {
  const std::string small = std::string(HRSPACE_SOURCE_DIR) + "/scenes/small_bedroom.json";
  const fs::path out = hrs::test_support::scratch_path("cli_restarts");
  fs::remove_all(out);
  ASSERT_EQ(run("design " + small + " --out " + (out / "three").string() +
                " --seed 1 --iterations 20 --restarts 3"),
            0);
  const auto report = nlohmann::json::parse(file_text(out / "three" / "report.json"));
  EXPECT_EQ(report["seed"], 1);  // the seed asked for; the chain kept has its own
  const auto& restarts = report["restarts"];
  ASSERT_EQ(restarts["chains"], 3);
  ASSERT_EQ(restarts["tried"].size(), 3u);
  EXPECT_EQ(restarts["tried"][0]["seed"], 1);  // chain 0 has the seed itself
  double least = 1e300;
  for (const auto& c : restarts["tried"]) least = std::min(least, c["cost"].get<double>());
  EXPECT_EQ(report["cost"]["final"].get<double>(), least);
  // The chain kept, alone: the same layout and tours, byte for byte.
  const std::string kept = std::to_string(restarts["kept_seed"].get<std::uint64_t>());
  ASSERT_EQ(run("design " + small + " --out " + (out / "alone").string() + " --seed " + kept +
                " --iterations 20 --restarts 1 --threads 1"),
            0);
  EXPECT_EQ(file_text(out / "three" / "layout.json"), file_text(out / "alone" / "layout.json"));
  EXPECT_EQ(file_text(out / "three" / "tours.json"), file_text(out / "alone" / "tours.json"));
  EXPECT_FALSE(nlohmann::json::parse(file_text(out / "alone" / "report.json")).contains("restarts"));
}

TEST(DesignCli, CtrlCWritesTheBestDesignSoFarAndExits130) {
  const fs::path out = hrs::test_support::scratch_path("cli_sigint");
  fs::remove_all(out);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string o = out.string();
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(kBin.c_str(), kBin.c_str(), "design", kBedroom.c_str(), "--out", o.c_str(),
          "--iterations", "100000", static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream in(out / "report.json");
  ASSERT_TRUE(in.good());
  const auto report = nlohmann::json::parse(in);
  EXPECT_TRUE(report["stopped"].get<bool>());
  EXPECT_LT(report["iterations_run"].get<int>(), 100000);
  EXPECT_TRUE(fs::exists(out / "layout.json"));
  EXPECT_TRUE(fs::exists(out / "design.svg"));
}

//! Starts a long design into `out`, sends `sig` after `ms`, returns the exit status.
int design_stopped_by(int sig, const fs::path& out, int ms = 2500) {
  const pid_t pid = fork();
  if (pid < 0) return -2;
  if (pid == 0) {
    const std::string o = out.string();
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(kBin.c_str(), kBin.c_str(), "design", kBedroom.c_str(), "--out", o.c_str(),
          "--iterations", "100000", static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  kill(pid, sig);
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -3;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Hardening (issue 20): SIGTERM and SIGHUP stop like Ctrl-C.
TEST(DesignCli, FaultsLoseNoData_SigtermAndSighupWriteTheBestDesign) {
  for (const int sig : {SIGTERM, SIGHUP}) {
    const fs::path out = hrs::test_support::scratch_path("cli_sig" + std::to_string(sig));
    fs::remove_all(out);
    EXPECT_EQ(design_stopped_by(sig, out), 128 + sig);
    std::ifstream in(out / "report.json");
    ASSERT_TRUE(in.good()) << sig;
    EXPECT_TRUE(nlohmann::json::parse(in)["stopped"].get<bool>());
    for (const auto& e : fs::directory_iterator(out))  // no temporary left behind
      if (e.path().filename() != ".hrspace.lock") {  // (the lock file stays, unlocked)
        EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
      }
  }
}

// Hardening: a rerun with fewer designs removes the earlier run's extra ones;
// foreign files in a numbered directory are refused before any work.
TEST(DesignCli, FaultsLoseNoData_StaleOutputsAreRemoved) {
  const fs::path out = hrs::test_support::scratch_path("cli_stale");
  fs::remove_all(out);
  ASSERT_EQ(run("design " + kBedroom + " --out " + out.string() + " --designs 3 --iterations 1"),
            0);
  ASSERT_TRUE(fs::exists(out / "3" / "layout.json"));
  std::string err;
  ASSERT_EQ(run("design " + kBedroom + " --out " + out.string() + " --designs 2 --iterations 1",
                &err),
            0);
  EXPECT_FALSE(fs::exists(out / "3"));
  EXPECT_TRUE(fs::exists(out / "2" / "layout.json"));
  EXPECT_NE(err.find("removed 1 stale output"), std::string::npos) << err;
  ASSERT_EQ(run("design " + kBedroom + " --out " + out.string() + " --iterations 1"), 0);
  EXPECT_FALSE(fs::exists(out / "1"));
  EXPECT_FALSE(fs::exists(out / "contact_sheet.svg"));
  EXPECT_TRUE(fs::exists(out / "layout.json"));
  fs::create_directories(out / "7");
  std::ofstream(out / "7" / "notes.txt") << "mine";
  EXPECT_EQ(run("design " + kBedroom + " --out " + out.string() + " --iterations 1", &err), 2);
  EXPECT_NE(err.find("notes.txt"), std::string::npos) << err;
  EXPECT_TRUE(fs::exists(out / "7" / "notes.txt"));
}

//! A scene at the format's limits whose sequence enumeration alone takes
//! seconds (16 s on this machine): 100 small objects, every move equally
//! likely, 100 visits, M = 1000.
std::string heavy_enumeration_scene() {
  nlohmann::json j;
  j["format"] = "hrspace-scene/1";
  j["name"] = "heavy_enumeration";
  j["room"] = {{"size", {30, 30}}};
  j["door"] = {{"center", {1.0, 0.0}}, {"width", 0.9}};
  j["wheelchair"] = {{"length", 1.1}, {"width", 0.65}, {"turning_radius", 0.7}};
  nlohmann::json objects = nlohmann::json::array(), transitions;
  for (int i = 0; i < 100; ++i) {
    const std::string id = "o" + std::to_string(i);
    objects.push_back(
        {{"id", id}, {"size", {0.4, 0.4}}, {"pose", {3.0 + 2.5 * (i % 10), 3.0 + 2.5 * (i / 10), 0.0}}});
    transitions["door"][id] = 0.01;
    for (int k = 0; k < 100; ++k) transitions[id]["o" + std::to_string(k)] = 0.01;
  }
  j["objects"] = objects;
  j["activity"] = {{"transitions", transitions}, {"visits", 100}, {"sequences", 1000}};
  return j.dump();
}

//! True once `pid` runs `kBin` (not the forked test) and catches SIGINT.
bool catches_sigint(pid_t pid) {
  std::ifstream cmdline("/proc/" + std::to_string(pid) + "/cmdline");
  std::string argv0;
  std::getline(cmdline, argv0, '\0');
  if (argv0 != kBin) return false;
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1) & 1) != 0;
  }
  return false;
}

// Hardening: Ctrl-C during a long sequence enumeration (before the first
// iteration) is honoured at once: exit 130, one line on stderr, nothing
// written. The signal is sent as soon as the command's handler is installed
// (the enumeration starts right after); without the stop check in the
// enumeration the command would run for minutes.
TEST(DesignCli, CtrlCDuringALongEnumerationExits130Promptly) {
  const fs::path dir = hrs::test_support::scratch_path("cli_enum");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "heavy.json", out = dir / "out", err = dir / "err.txt";
  std::ofstream(scene) << heavy_enumeration_scene();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string s = scene.string(), o = out.string();
    freopen("/dev/null", "w", stdout);
    freopen(err.c_str(), "w", stderr);
    execl(kBin.c_str(), kBin.c_str(), "design", s.c_str(), "--out", o.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  using Clock = std::chrono::steady_clock;
  auto deadline = Clock::now() + std::chrono::seconds(60);
  int status = 0;
  pid_t done = 0;
  while (!catches_sigint(pid) && Clock::now() < deadline &&
         (done = waitpid(pid, &status, WNOHANG)) == 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(done, 0) << "hrspace design ended before it caught SIGINT";
  ASSERT_TRUE(catches_sigint(pid)) << "no SIGINT handler within 60 s";
  kill(pid, SIGINT);
  const auto sent = Clock::now();
  deadline = sent + std::chrono::seconds(20);
  while ((done = waitpid(pid, &status, WNOHANG)) == 0 && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "hrspace design still running 20 s after SIGINT";
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  std::printf("exited %.2f s after SIGINT\n", seconds);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream in(err);
  std::stringstream message;
  message << in.rdbuf();
  EXPECT_EQ(message.str(), "hrspace design: interrupted before the first iteration; nothing written\n");
  EXPECT_FALSE(fs::exists(out / "layout.json"));
  EXPECT_FALSE(fs::exists(out / "report.json"));
  fs::remove_all(dir);
}

// Hardening: --out is checked before the work, not after it.
TEST(DesignCli, FaultsLoseNoData_UnwritableOutIsRefusedFirst) {
  const fs::path file = hrs::test_support::scratch_path("cli_file");
  std::ofstream(file) << "x";
  std::string err;
  // 100000 iterations would run for many minutes: refused before any work,
  // the one line names --out's path (the suite's external timeout bounds it).
  EXPECT_EQ(run("design " + kBedroom + " --out " + (file / "sub").string() +
                    " --iterations 100000",
                &err),
            2);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
  EXPECT_NE(err.find((file / "sub").string()), std::string::npos) << err;
  fs::remove(file);
}

}  // namespace
