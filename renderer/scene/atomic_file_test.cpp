#include "scene/atomic_file.h"

#include "scene/scene_io.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct AtomicFile : ::testing::Test {
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("wavelit_atomic_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir);
    }
    size_t entries() const { return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

TEST_F(AtomicFile, WritesAndReplacesLeavingNoTemporaries) {
    const fs::path f = dir / "a.wlscene";
    ASSERT_TRUE(writeFileAtomic(f.string(), "first").ok());
    EXPECT_EQ(readBytes(f), "first");
    ASSERT_TRUE(writeFileAtomic(f.string(), "second, longer").ok());
    EXPECT_EQ(readBytes(f), "second, longer");
    EXPECT_EQ(entries(), 1u);
    EXPECT_EQ(fs::status(f).permissions() & fs::perms::owner_read, fs::perms::owner_read);
}

// Full disk, simulated by a writer that fails with ENOSPC half-way (a real /dev/full cannot be
// renamed over, so it would test the wrong step).
TEST_F(AtomicFile, FullDiskLeavesTheOldFileByteIdentical) {
    const fs::path f = dir / "a.wllight";
    const std::string old(4096, 'x');
    ASSERT_TRUE(writeFileAtomic(f.string(), old).ok());
    AtomicWriteOptions full;
    full.write = [](int fd, const char* data, size_t size) -> long {
        if (size > 100) return long(::write(fd, data, 100));
        errno = ENOSPC;
        return -1;
    };
    auto s = writeFileAtomic(f.string(), std::string(8192, 'y'), full);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().kind, util::ErrorKind::Io);
    EXPECT_NE(s.error().reason.find("No space left on device"), std::string::npos) << s.error().message();
    EXPECT_NE(s.error().reason.find("unchanged"), std::string::npos);
    EXPECT_EQ(readBytes(f), old);
    EXPECT_EQ(entries(), 1u); // the temporary is gone
}

TEST_F(AtomicFile, ParentThatIsAFileIsReported) {
    const fs::path blocker = dir / "blocker";
    ASSERT_TRUE(writeFileAtomic(blocker.string(), "i am a file").ok());
    auto s = writeFileAtomic((blocker / "x.wlscene").string(), "data");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().reason.find("Not a directory"), std::string::npos) << s.error().message();
    EXPECT_EQ(readBytes(blocker), "i am a file");
}

// A read-only folder; root ignores permissions, so there the check would be meaningless.
TEST_F(AtomicFile, ReadOnlyFolderLeavesTheOldFileByteIdentical) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders; covered by the full-disk test";
    const fs::path f = dir / "a.wlscene";
    ASSERT_TRUE(writeFileAtomic(f.string(), "old").ok());
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    auto s = writeFileAtomic(f.string(), "new");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().reason.find("Permission denied"), std::string::npos) << s.error().message();
    EXPECT_EQ(readBytes(f), "old");
}

TEST_F(AtomicFile, FailedSceneSaveKeepsThePreviousScene) {
    Scene scene;
    scene.name = "kept";
    const fs::path f = dir / "s.wlscene";
    ASSERT_TRUE(saveScene(scene, f.string()).ok());
    const std::string before = readBytes(f);
    // Replace the file's folder entry with a directory so the rename must fail.
    const fs::path asDir = dir / "d.wlscene";
    fs::create_directories(asDir / "inner");
    auto s = saveScene(scene, asDir.string());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message().find("d.wlscene"), std::string::npos);
    EXPECT_NE(s.error().reason.find("cannot replace the file"), std::string::npos) << s.error().message();
    EXPECT_TRUE(fs::is_directory(asDir / "inner"));
    EXPECT_EQ(readBytes(f), before);
    EXPECT_EQ(entries(), 2u);
}

} // namespace
} // namespace wavelit::scene
