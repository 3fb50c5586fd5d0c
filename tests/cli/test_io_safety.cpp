// Where output goes when the process is started oddly or pointed at odd
// files: closed standard descriptors (`2>&-`: a frame file took fd 2 and
// got the progress lines), standard output or stderr on a full disk
// (`> /dev/full` exited 0), and --junit naming a FIFO, a character device, a socket or a
// directory (the atomic rename replaced a FIFO and /dev/null by files).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const char* kMain =
    "float h(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }\n"
    "void mainImage(out vec4 c, in vec2 f) { c = vec4(h(f), h(f + 17.0), h(f + iTime), 1.0); }\n";

// A shell prefix that runs marchstudio with `redirections` applied after
// run_marchstudio's own (which give the shell its stdout, stderr and stdin).
std::string exec_with(const std::string& redirections) { return "sh -c 'exec \"$0\" \"$@\" " + redirections + "' "; }

std::string frame_name(int k) { return "f_0" + std::to_string(k) + ".png"; }

TEST(ClosedStdFds, SequenceFramesHoldNothingButTheImageWithStderrClosed) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const std::vector<std::string> args = {"render", "m.glsl", "--size", "320x180",
                                        "--frames", "0..7", "-o", "f_%02d.png"};
  const RunResult r = run_marchstudio(args, dir.path(), exec_with("2>&-"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // The same frames, rendered with stderr open: byte for byte what the closed run wrote.
  TempDir ref;
  write_file(ref / "m.glsl", kMain);
  const RunResult open = run_marchstudio(args, ref.path());
  ASSERT_EQ(open.exit_code, 0) << open.err;
  for (int k = 0; k < 8; ++k) {
    const std::string bytes = read_file(dir / frame_name(k));
    EXPECT_EQ(bytes.find("marchstudio: frame"), std::string::npos) << frame_name(k) << " holds a progress line";
    EXPECT_TRUE(bytes == read_file(ref / frame_name(k))) << frame_name(k) << " differs from the frame with stderr open";
    const Image img = read_image(dir / frame_name(k));  // throws when it does not decode
    EXPECT_EQ(img.width, 320);
  }
}

// ffprobe's pipe took fd 1 when stdin and stdout were closed, and its
// output went where marchstudio's stdout would: the video was refused.
TEST(ClosedStdFds, VideoInputDecodesWithStdinAndStdoutClosed) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  const std::string make = "cd '" + dir.path().string() +
                           "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f lavfi -i testsrc=size=8x6:rate=4 "
                           "-t 2 -c:v ffv1 clip.mkv";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  write_file(dir / "v.json",
             "{\"Shader\": {\"info\": {\"name\": \"v\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
             "\"code\": \"void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }\", "
             "\"inputs\": [{\"id\": 1, \"ctype\": \"video\", \"channel\": 0, \"src\": \"/media/a/clip.mkv\", "
             "\"sampler\": {\"filter\": \"linear\", \"wrap\": \"clamp\", \"vflip\": \"true\", \"srgb\": \"false\"}}], "
             "\"outputs\": []}]}}");
  const RunResult r = run_marchstudio({"render", "v.json", "--media-dir", ".", "--size", "8x6", "-o", "o.png"},
                                      dir.path(), exec_with("<&- >&-"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "o.png")) << r.err;
}

// A passing one-case suite in `dir`: its reference rendered first.
fs::path passing_suite(const TempDir& dir) {
  write_file(dir / "m.glsl", kMain);
  EXPECT_EQ(run_marchstudio({"render", "m.glsl", "--size", "16x16", "-o", "ref.png"}, dir.path()).exit_code, 0);
  write_file(dir / "s.toml",
             "[[case]]\nname = \"ok\"\nscene = \"m.glsl\"\nsize = [16, 16]\nreference = \"ref.png\"\n"
             "metric = \"psnr\"\nthreshold = 40\n");
  return dir / "s.toml";
}

TEST(StdoutFull, EveryCommandThatPrintsExitsThree) {
  TempDir dir;
  passing_suite(dir);
  const std::vector<std::vector<std::string>> commands = {
      {"render", "m.glsl", "--print-shader"}, {"info", "ref.png"}, {"test", "s.toml", "--json"}, {"--help"}};
  for (const auto& args : commands) {
    const RunResult r = run_marchstudio(args, dir.path(), exec_with(">/dev/full"));
    EXPECT_EQ(r.exit_code, 3) << args.front() << ": " << r.err;
    EXPECT_NE(r.err.find("marchstudio: cannot write to standard output"), std::string::npos) << r.err;
  }
  // The same with stdout to a file: nothing failed, exit 0.
  const RunResult ok = run_marchstudio({"info", "ref.png"}, dir.path());
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  // The log lost (stderr on a full disk) is an I/O failure too.
  const RunResult log = run_marchstudio({"render", "m.glsl", "--size", "16x16", "-v", "-o", "o.png"}, dir.path(),
                                        exec_with("2>/dev/full"));
  EXPECT_EQ(log.exit_code, 3);
}

struct stat stat_of(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
  return st;
}

TEST(JunitTarget, AFifoStaysAFifoAndItsReaderGetsTheXml) {
  TempDir dir;
  const fs::path suite = passing_suite(dir);
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  // The reader: open before the run (without waiting for a writer); the
  // XML is far less than a pipe holds, so the writer never waits on it.
  const int fd = ::open((dir / "pipe").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  const RunResult r = run_marchstudio({"test", suite.string(), "--junit", "pipe"}, dir.path());
  std::string got;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) got.append(buf, static_cast<size_t>(n));
  ::close(fd);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(S_ISFIFO(stat_of(dir / "pipe").st_mode));
  EXPECT_EQ(got.rfind("<?xml", 0), 0u) << got;
  EXPECT_NE(got.find("</testsuites>"), std::string::npos) << got;
}

TEST(JunitTarget, ACharacterDeviceStaysOne) {
  TempDir dir;
  const fs::path suite = passing_suite(dir);
  // A null device of our own where we may make one (root): should the rule
  // break, the test's copy is replaced, not the system's /dev/null. Without
  // root /dev/null itself, which only root could replace.
  fs::path null = dir / "null";
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) null = "/dev/null";
  const RunResult r = run_marchstudio({"test", suite.string(), "--junit", null.string()}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const struct stat st = stat_of(null);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(st.st_rdev, ::makedev(1, 3));
}

TEST(JunitTarget, ASocketOrADirectoryIsRefusedBeforeTheRun) {
  TempDir dir;
  const fs::path suite = passing_suite(dir);
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string path = (dir / "sock").string();
  ASSERT_LT(path.size(), sizeof addr.sun_path);
  path.copy(addr.sun_path, path.size());
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  fs::create_directory(dir / "dir");
  for (const char* target : {"sock", "dir"}) {
    const RunResult r = run_marchstudio({"test", suite.string(), "--junit", target}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << target << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--junit"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("pass"), std::string::npos) << "the suite ran first: " << r.out;
  }
  EXPECT_TRUE(S_ISSOCK(stat_of(dir / "sock").st_mode));
  EXPECT_TRUE(fs::is_empty(dir / "dir"));
  ::close(s);
}

}  // namespace
}  // namespace ms::test
