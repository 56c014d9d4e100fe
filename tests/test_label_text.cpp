// Label texts: numbers that cannot be misread turned, part letters, mate labels.
#include <gtest/gtest.h>

#include "foldkit/layout/label_text.hpp"

using namespace foldkit::layout;

TEST(LabelText, NumbersThatReadAsAnotherNumberTurnedAreRecognised) {
  for (int n : {6, 9, 16, 18, 19, 61, 66, 68, 81, 86, 89, 91, 98, 99, 106, 109, 168, 1006})
    EXPECT_TRUE(reads_as_other_number_turned(n)) << n;
  // Read the same turned (0, 1, 8, 11, 69, 88, 96, 101, 609), turn into no number (10, 60, 100: a
  // leading zero), or contain a digit that turns into no digit.
  for (int n : {0, 1, 8, 11, 69, 88, 96, 101, 609, 10, 60, 100, 2, 12, 26, 67, 97, 123})
    EXPECT_FALSE(reads_as_other_number_turned(n)) << n;
}

TEST(LabelText, AmbiguousNumbersArePrintedWithATrailingPeriod) {
  EXPECT_EQ(number_text(6), "6.");
  EXPECT_EQ(number_text(9), "9.");
  EXPECT_EQ(number_text(86), "86.");
  EXPECT_EQ(number_text(69), "69");
  EXPECT_EQ(number_text(12), "12");
}

TEST(LabelText, PartLettersRunLikeSpreadsheetColumnsWithoutIAndO) {
  EXPECT_EQ(piece_letter(0), "A");
  EXPECT_EQ(piece_letter(7), "H");
  EXPECT_EQ(piece_letter(8), "J");  // no I: "I 135" reads as 1135
  EXPECT_EQ(piece_letter(12), "N");
  EXPECT_EQ(piece_letter(13), "P");  // no O: "O 10" reads as 010
  EXPECT_EQ(piece_letter(23), "Z");
  EXPECT_EQ(piece_letter(24), "AA");
  EXPECT_EQ(piece_letter(25), "AB");
  EXPECT_EQ(piece_letter(47), "AZ");
  EXPECT_EQ(piece_letter(48), "BA");
  EXPECT_EQ(piece_letter(24 * 25 - 1), "ZZ");
  EXPECT_EQ(piece_letter(24 * 25), "AAA");
}

TEST(LabelText, NoPartLetterHoldsAnIOrAnOAndEachReadsBackAsItsRank) {
  for (int i = 0; i < 5000; ++i) {
    const std::string letter = piece_letter(i);
    EXPECT_EQ(letter.find_first_of("IO"), std::string::npos) << i << ": " << letter;
    EXPECT_EQ(letter_rank(letter), i) << letter;
  }
}

TEST(LabelText, ASeamLabelNamesItsMatesPartAndSheetOnlyWhenThoseDiffer) {
  EXPECT_EQ(seam_label_text(12, "", 0), "12");
  EXPECT_EQ(seam_label_text(12, "B", 0), "B12");
  EXPECT_EQ(seam_label_text(12, "B", 3), "B12 p3");
  EXPECT_EQ(seam_label_text(9, "AA", 11), "AA9. p11");
  EXPECT_EQ(seam_label_text(12, "", 3), "12");  // inside one part the mate is on the same sheet
}

TEST(LabelText, AListedSeamIsNamedByItsPartsAndNumber) {
  EXPECT_EQ(seam_name(7, "", ""), "7");
  EXPECT_EQ(seam_name(7, "A", "A"), "A 7");
  EXPECT_EQ(seam_name(3, "B", "A"), "A-B 3");
  EXPECT_EQ(seam_name(3, "A", "B"), "A-B 3");
  EXPECT_EQ(seam_name(9, "Z", "AA"), "Z-AA 9.");  // by rank, not by spelling
}

TEST(LabelText, TheSeamNumberIsReadBackFromAnyLabelForm) {
  EXPECT_EQ(seam_number_in("12"), 12);
  EXPECT_EQ(seam_number_in("9."), 9);
  EXPECT_EQ(seam_number_in("B12 p3"), 12);
  EXPECT_EQ(seam_number_in("AA16. p11"), 16);
  EXPECT_EQ(seam_number_in("(7)"), 7);
  EXPECT_EQ(seam_number_in("A"), 0);
}

TEST(LabelText, WhatIsNoPartLetterHasNoRank) {
  EXPECT_EQ(letter_rank(""), -1);
  EXPECT_EQ(letter_rank("I"), -1);
  EXPECT_EQ(letter_rank("a"), -1);
  EXPECT_EQ(letter_rank("AAAAAAAA"), -1);
}
