// The checkpoint file's text: every double reads back bit for bit (the resumed run is the
// uninterrupted one only if they do), text with any characters comes back, and a line that does
// not fit is refused at its line and key.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tumble/simulation/checkpoint_file.hpp"
#include "tumble/simulation/text_archive.hpp"

namespace tumble {
namespace {

struct Fields {
  double x = 0.0;
  long n = 0;
  VecX v;
  std::string what;
  std::vector<double> list;
};

void archive(StateArchive& a, Fields& f) {
  a.enter("part");
  a.number("x", f.x);
  a.integer("n", f.n);
  a.numbers("v", f.v);
  a.text("what", f.what);
  a.list("list", f.list, [](StateArchive& item, double& value) { item.number("value", value); });
  a.leave();
}

std::string written(Fields f) {
  TextArchiveWriter out;
  archive(out, f);
  return out.written();
}

Fields read(const std::string& text) {
  TextArchiveReader in(text, "state");
  Fields f;
  archive(in, f);
  EXPECT_TRUE(in.at_end());
  return f;
}

TEST(TextArchive, EveryDoubleReadsBackBitForBit) {
  const double hard[] = {0.1,
                         -0.0,
                         1.0 / 3.0,
                         std::nextafter(1.0, 2.0),
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::max(),
                         -std::numeric_limits<double>::infinity(),
                         0.70984206108953474,
                         6.02214076e23};
  for (const double x : hard) {
    Fields f;
    f.x = x;
    f.v = VecX::Constant(3, x);
    f.list = {x, -x};
    const Fields back = read(written(f));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back.x), std::bit_cast<std::uint64_t>(x)) << x;
    for (const double y : back.v) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(y), std::bit_cast<std::uint64_t>(x));
    }
    ASSERT_EQ(back.list.size(), 2u);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back.list[1]), std::bit_cast<std::uint64_t>(-x));
  }
  Fields nan;
  nan.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(read(written(nan)).x));
}

TEST(TextArchive, TextWithNewlinesAndBackslashesComesBack) {
  Fields f;
  f.what = "impact: normal speed 4.4 -> 3.5 m/s\\n\nsecond line \\ end";
  f.n = -42;
  EXPECT_EQ(read(written(f)).what, f.what);
  EXPECT_EQ(read(written(f)).n, -42);
}

TEST(TextArchive, ALineThatDoesNotFitIsRefusedAtItsLineAndKey) {
  Fields f;
  f.v = VecX::Ones(2);
  f.list = {1.0};
  const std::string good = written(f);
  const auto refusal = [](const std::string& text) {
    try {
      read(text);
    } catch (const CheckpointFileError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_EQ(refusal(replaced("part.x 0", "part.x zero")),
            "state:1: part.x: 'zero' is not a number");
  EXPECT_EQ(refusal(replaced("part.n 0", "part.m 0")),
            "state:2: part.n: expected this field here, found 'part.m'");
  EXPECT_EQ(refusal(replaced("part.v 2 1 1", "part.v 3 1 1")),
            "state:3: part.v: fewer numbers on the line than its length, 3");
  EXPECT_EQ(refusal(replaced("part.v 2 1 1", "part.v 1 1 1")),
            "state:3: part.v: more than the 1 numbers its length says");
  EXPECT_NE(refusal(replaced("part.list.size 1", "part.list.size 1000000000000"))
                .find("more items than fields are left"),
            std::string::npos);
  EXPECT_EQ(refusal(good.substr(0, good.find("part.what"))),
            "state:3: part.what: the file ends before this field: it is cut short");
}

}  // namespace
}  // namespace tumble
