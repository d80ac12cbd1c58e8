#pragma once
// Reading a Lab family's report in tests: a method's named error figure and its
// failure count by cause.
#include <sherpa/lab/family.h>

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

namespace sherpa::test {

// The value of `m`'s error figure `name`; a test failure and -1 where it has none.
inline double figure(const lab::MethodResult& m, const std::string& name) {
    const lab::ErrorFigure* e = m.error(name);
    EXPECT_NE(e, nullptr) << m.method.name << " " << m.method.parameters << " has no " << name;
    return e ? e->value : -1.0;
}

// How many failures of `cause` `m` counted.
inline std::uint64_t failures(const lab::MethodResult& m, const std::string& cause) {
    std::uint64_t n = 0;
    for (const lab::Failure& f : m.failures) n += f.cause == cause ? f.count : 0;
    return n;
}

} // namespace sherpa::test
