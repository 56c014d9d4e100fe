// Paper presets, custom sizes and lengths as users type them.
#include <gtest/gtest.h>

#include "foldkit/layout/paper.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Paper, PresetsAreFoundWhateverTheCase) {
  EXPECT_EQ(parse_paper("A4"), (Vec2{210, 297}));
  EXPECT_EQ(parse_paper("a3"), (Vec2{297, 420}));
  EXPECT_EQ(parse_paper("A5"), (Vec2{148, 210}));
  EXPECT_EQ(parse_paper("LETTER"), (Vec2{215.9, 279.4}));
  EXPECT_EQ(parse_paper("legal"), (Vec2{215.9, 355.6}));
  EXPECT_EQ(parse_paper("12x12in"), (Vec2{304.8, 304.8}));
  EXPECT_EQ(parse_paper("mat12"), (Vec2{304.8, 304.8}));
}

TEST(Paper, CustomSizesTakeMillimetresCentimetresOrInches) {
  EXPECT_EQ(parse_paper("210x297mm"), (Vec2{210, 297}));
  EXPECT_EQ(parse_paper("100x150"), (Vec2{100, 150}));
  EXPECT_EQ(parse_paper("30x40cm"), (Vec2{300, 400}));
  auto letter = parse_paper("8.5x11in");
  ASSERT_TRUE(letter);
  EXPECT_NEAR(letter->x, 215.9, 1e-9);
  EXPECT_NEAR(letter->y, 279.4, 1e-9);
}

TEST(Paper, NonsenseIsRejected) {
  for (const char* bad :
       {"", "B7", "x", "210x", "x297", "0x297mm", "-210x297", "210x297km", "210*297", "nanxnan", "1e999x5"})
    EXPECT_FALSE(parse_paper(bad)) << bad;
}

TEST(Paper, OrientationTurnsTheSheetWithoutChangingIt) {
  EXPECT_EQ(oriented({210, 297}, Orientation::Portrait), (Vec2{210, 297}));
  EXPECT_EQ(oriented({210, 297}, Orientation::Landscape), (Vec2{297, 210}));
  EXPECT_EQ(oriented({297, 210}, Orientation::Portrait), (Vec2{210, 297}));
}

TEST(Paper, LengthsHaveOptionalUnitsAndMustBePositive) {
  EXPECT_EQ(parse_length_mm("150mm"), 150);
  EXPECT_EQ(parse_length_mm("150"), 150);
  EXPECT_EQ(parse_length_mm("15cm"), 150);
  EXPECT_EQ(parse_length_mm("2in"), 50.8);
  EXPECT_EQ(parse_length_mm("2.5MM"), 2.5);
  for (const char* bad : {"", "mm", "-3mm", "0", "12parsecs", "5m", "nan", "inf", "1e400"})
    EXPECT_FALSE(parse_length_mm(bad)) << bad;
}

TEST(Paper, NamesForMessagesListEveryPreset) {
  const std::string names = paper_names();
  for (const PaperPreset& p : paper_presets())
    EXPECT_NE(names.find(p.name), std::string::npos) << p.name;
}
