#include "scene/load_guard.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace wavelit::scene {
namespace {

TEST(LoadGuard, PassesResultsThrough) {
    auto ok = guardLoad<int>("a.exr", [] { return util::Result<int>(7); });
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(*ok, 7);
    auto error = guardLoad<int>("a.exr", [] { return util::Result<int>(util::makeError(util::ErrorKind::Invalid, "a.exr", "bad")); });
    ASSERT_FALSE(error.ok());
    EXPECT_EQ(error.error().message(), "a.exr: bad");
}

TEST(LoadGuard, TurnsAnEscapingExceptionIntoAnErrorNamingTheFile) {
    auto thrown = guardLoad<int>("b.wlscene", []() -> util::Result<int> { throw std::out_of_range("index 9"); });
    ASSERT_FALSE(thrown.ok());
    EXPECT_EQ(thrown.error().message(), "b.wlscene: " + std::string(kUnexpectedLoadFailure) + "index 9");
    auto oom = guardLoad<int>("c.obj", []() -> util::Result<int> { throw std::bad_alloc(); });
    ASSERT_FALSE(oom.ok());
    EXPECT_EQ(oom.error().message(), "c.obj: " + std::string(kUnexpectedLoadFailure) + "out of memory");
    auto odd = guardLoad<int>("d.ply", []() -> util::Result<int> { throw 42; });
    ASSERT_FALSE(odd.ok());
    EXPECT_EQ(odd.error().kind, util::ErrorKind::Format);
}

} // namespace
} // namespace wavelit::scene
