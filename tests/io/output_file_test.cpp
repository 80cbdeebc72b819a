#include "stratum/io/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "stratum/io/json.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

namespace fs = std::filesystem;

/// A fresh folder per test (ctest runs the cases in parallel).
fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("stratum_output_file_test_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(io::OutputFile& file, const std::string& text) {
  file.write([&](std::ostream& out) { out << text; });
}

/// Names in `dir` that are staging files.
std::vector<std::string> staging_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(io::staging_marker) != std::string::npos)
      found.push_back(entry.path().filename().string());
  return found;
}

std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFile, WritesANewFileAndLeavesNoStagingFile) {
  const fs::path dir = scratch("new");
  io::OutputFile file("output", (dir / "a.txt").string());
  file.prepare();
  EXPECT_EQ(staging_files(dir).size(), 1u);  // staged before any work
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
  write_text(file, "hello\n");
  file.commit();
  EXPECT_EQ(slurp(dir / "a.txt"), "hello\n");
  EXPECT_TRUE(staging_files(dir).empty());
  fs::remove_all(dir);
}

TEST(OutputFile, KeepsTheReplacedFilesPermissions) {
  const fs::path dir = scratch("mode");
  const fs::path target = dir / "a.txt";
  std::ofstream(target) << "old\n";
  ASSERT_EQ(chmod(target.c_str(), 0640), 0);
  io::OutputFile file("output", target.string());
  file.prepare();
  write_text(file, "new\n");
  file.commit();
  struct stat info {};
  ASSERT_EQ(stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
  EXPECT_EQ(slurp(target), "new\n");
  if (geteuid() == 0) {  // root rewriting another user's file gives it back to that user
    ASSERT_EQ(chown(target.c_str(), 4321, 4322), 0);
    io::OutputFile again("output", target.string());
    write_text(again, "newer\n");
    again.commit();
    ASSERT_EQ(stat(target.c_str(), &info), 0);
    EXPECT_EQ(info.st_uid, 4321u);
    EXPECT_EQ(info.st_gid, 4322u);
    EXPECT_EQ(info.st_mode & 07777, 0640u);
  }
  fs::remove_all(dir);
}

TEST(OutputFile, WritesThroughASymbolicLinkAndKeepsTheLink) {
  const fs::path dir = scratch("link");
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "a.txt") << "old\n";
  fs::create_symlink("real/a.txt", dir / "link.txt");
  io::OutputFile file("output", (dir / "link.txt").string());
  file.prepare();
  write_text(file, "new\n");
  file.commit();
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(slurp(dir / "real" / "a.txt"), "new\n");
  EXPECT_TRUE(staging_files(dir).empty());
  EXPECT_TRUE(staging_files(dir / "real").empty());
  // A dangling link: the file it names is created.
  fs::create_symlink("real/b.txt", dir / "dangling.txt");
  io::OutputFile second("output", (dir / "dangling.txt").string());
  write_text(second, "b\n");
  second.commit();
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(slurp(dir / "real" / "b.txt"), "b\n");
  fs::remove_all(dir);
}

TEST(OutputFile, RefusesAFileWithSeveralHardLinksAndLeavesIt) {
  const fs::path dir = scratch("hard");
  std::ofstream(dir / "a.txt") << "old\n";
  fs::create_hard_link(dir / "a.txt", dir / "b.txt");
  io::OutputFile file("output", (dir / "a.txt").string());
  const std::string message = message_of([&] { file.prepare(); });
  EXPECT_NE(message.find("invalid output = " + (dir / "a.txt").string()), std::string::npos) << message;
  EXPECT_NE(message.find("2 hard links"), std::string::npos) << message;
  EXPECT_EQ(slurp(dir / "b.txt"), "old\n");
  EXPECT_EQ(fs::hard_link_count(dir / "a.txt"), 2u);
  EXPECT_TRUE(staging_files(dir).empty());
  fs::remove_all(dir);
}

TEST(OutputFile, RefusesAFolderOrAMissingFolderWhenPrepared) {
  const fs::path dir = scratch("folder");
  io::OutputFile folder("output", dir.string());
  EXPECT_NE(message_of([&] { folder.prepare(); }).find("is a folder"), std::string::npos);
  io::OutputFile missing("exr", (dir / "no" / "such" / "x.exr").string());
  const std::string message = message_of([&] { missing.prepare(); });
  EXPECT_NE(message.find("invalid exr = "), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(OutputFile, WritesIntoAFifoAndLeavesItAFifo) {
  const fs::path dir = scratch("fifo");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  io::OutputFile file("output", fifo.string());
  file.prepare();
  EXPECT_TRUE(file.special());
  write_text(file, "through the pipe\n");
  file.commit();
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  struct stat info {};
  ASSERT_EQ(stat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
  fs::remove_all(dir);
}

TEST(OutputFile, AnUncommittedOutputLeavesNothing) {
  const fs::path dir = scratch("discard");
  {
    io::OutputFile file("output", (dir / "a.txt").string());
    write_text(file, "never committed\n");
  }
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(OutputFile, RemovesStagingFilesOfDeadProcessesOnly) {
  const fs::path dir = scratch("stale");
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0);  // a PID that is no longer running
  const std::string dead = ".a.txt" + std::string(io::staging_marker) + std::to_string(child) + "-0.txt";
  const std::string alive = ".b.txt" + std::string(io::staging_marker) + std::to_string(getppid()) + "-0.txt";
  std::ofstream(dir / dead) << "left by kill -9\n";
  std::ofstream(dir / alive) << "another process, still writing\n";
  const std::string dead_folder = ".report" + std::string(io::staging_marker) + std::to_string(child) + "-3";
  fs::create_directories(dir / dead_folder / "figures");
  io::OutputFile file("output", (dir / "c.txt").string());
  write_text(file, "c\n");
  file.commit();
  EXPECT_FALSE(fs::exists(dir / dead));
  EXPECT_FALSE(fs::exists(dir / dead_folder));
  EXPECT_TRUE(fs::exists(dir / alive));
  const fs::path folder = io::make_staging_folder(dir, "page");
  EXPECT_TRUE(fs::is_directory(folder));
  EXPECT_EQ(
      folder.filename().string().rfind(".page" + std::string(io::staging_marker) + std::to_string(getpid()) + "-", 0),
      0u)
      << folder;
  fs::remove_all(dir);
}

TEST(OutputGroup, RefusesTwoOutputsNamingTheSameFile) {
  const fs::path dir = scratch("same");
  std::ofstream(dir / "a.exr") << "x";
  fs::create_symlink("a.exr", dir / "alias.exr");
  for (const std::string& second :
       {(dir / "a.exr").string(), (dir / "alias.exr").string(), (dir / "." / "a.exr").string()}) {
    io::OutputGroup group;
    group.add("exr", (dir / "a.exr").string());
    group.add("variance", second);
    const std::string message = message_of([&] { group.prepare(); });
    EXPECT_NE(message.find("invalid variance = " + second), std::string::npos) << message;
    EXPECT_NE(message.find("same file as --exr"), std::string::npos) << message;
  }
  io::OutputGroup fresh;  // not there yet: the same path
  fresh.add("output", (dir / "new.png").string());
  fresh.add("exr", (dir / "sub" / ".." / "new.png").string());
  fs::create_directories(dir / "sub");
  EXPECT_NE(message_of([&] { fresh.prepare(); }).find("same file"), std::string::npos);
  EXPECT_EQ(staging_files(dir).size(), 0u);
  fs::remove_all(dir);
}

TEST(OutputGroup, AFailedLaterCommitRemovesTheEarlierOutputs) {
  const fs::path dir = scratch("group");
  io::OutputGroup group;
  io::OutputFile* first = group.add("output", (dir / "a.png").string());
  io::OutputFile* second = group.add("exr", (dir / "b.exr").string());
  EXPECT_EQ(group.add("variance", ""), nullptr);
  group.prepare();
  write_text(*first, "a");
  write_text(*second, "b");
  fs::remove(second->staging());  // the second cannot be put in place
  EXPECT_THROW(group.commit(), invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "a.png"));
  EXPECT_FALSE(fs::exists(dir / "b.exr"));
  fs::remove_all(dir);
}

TEST(OutputFile, AFullDiskIsAnErrorAndLeavesNoFile) {
  const fs::path dir = scratch("full");
  if (mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (" << std::strerror(errno) << "; needs root)";
  std::string message;
  {
    io::OutputFile file("output", (dir / "big.txt").string());
    message = message_of([&] { write_text(file, std::string(1 << 20, 'x')); });
  }
  EXPECT_NE(message.find("invalid output = " + (dir / "big.txt").string()), std::string::npos) << message;
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(dir));
  umount(dir.c_str());
  fs::remove_all(dir);
}

TEST(RegularInput, RefusesAFifoWithoutOpeningIt) {
  const fs::path dir = scratch("input");
  ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
  const std::string message = message_of([&] { io::read_regular_file("scene", (dir / "pipe").string()); });
  EXPECT_NE(message.find("invalid scene = " + (dir / "pipe").string()), std::string::npos) << message;
  EXPECT_NE(message.find("a FIFO"), std::string::npos) << message;
  EXPECT_NE(message_of([&] { io::refuse_special_file("scene", (dir / "pipe").string()); }).find("regular file"),
            std::string::npos);
  EXPECT_EQ(message_of([&] { io::refuse_special_file("scene", (dir / "absent").string()); }), "");
  std::ofstream(dir / "text") << "abc";
  EXPECT_EQ(io::read_regular_file("scene", (dir / "text").string()), "abc");
  fs::remove_all(dir);
}

TEST(Json, DeepNestingIsRefusedWithPlaceAndAShortMessage) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string message = message_of([&] { io::parse_json(deep, "scene", "deep.json"); });
  EXPECT_NE(message.find("invalid scene = deep.json"), std::string::npos) << message;
  EXPECT_NE(message.find("deeper than 256 levels at line 1, column 257"), std::string::npos) << message;
  EXPECT_LT(message.size(), 300u);
  const std::string broken = message_of([&] { io::parse_json("{\n  \"a\": [1, 2,, 3]\n}", "configs", "c.json"); });
  EXPECT_NE(broken.find("is not valid JSON at line 2, column 14 (near '  \"a\": [1, 2,, 3]')"), std::string::npos)
      << broken;
  EXPECT_EQ(broken.find("json.exception"), std::string::npos) << broken;
  EXPECT_EQ(io::parse_json(std::string(256, '[') + std::string(256, ']'), "a", "b").size(), 1u);
  EXPECT_EQ(io::json_excerpt(nlohmann::json(std::string(500, 'a'))).size(), 63u);
}

}  // namespace
}  // namespace stratum
