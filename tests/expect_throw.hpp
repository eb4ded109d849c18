#pragma once
// Error text is part of the interface (STYLE: test the message, not only that an error was
// raised): runs f, expects it to throw E, and checks that the message contains `expected`.
#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace tumble::test {

template <typename E>
void expect_throw_containing(const std::function<void()>& f, const std::string& expected) {
  try {
    f();
    ADD_FAILURE() << "expected an exception containing \"" << expected << "\"; nothing thrown";
  } catch (const E& error) {
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos)
        << "message \"" << error.what() << "\" lacks \"" << expected << "\"";
  }
}

}  // namespace tumble::test
