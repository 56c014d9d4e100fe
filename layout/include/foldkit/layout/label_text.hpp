#pragma once
// What labels say: seam numbers that cannot be misread upside down, part letters, and the text a seam
// label carries on each side (the mate's part letter and sheet when it lies elsewhere).
#include <string>

namespace foldkit::layout {

/// True when `number`, turned 180 degrees, reads as a different number: every digit is one of
/// 0 1 6 8 9 (which turn into 0 1 9 8 6), and the turned digits, read in reverse order, form another
/// number without a leading zero (6, 9, 16, 18, 61, 66, 68, 81, 86, 89, 91, 98, 99, 106, ...; not 8,
/// 69, 88 or 10, which read the same or as no number).
bool reads_as_other_number_turned(int number);

/// The number as printed: with a trailing period when it reads as another number turned ("6." "9.").
std::string number_text(int number);

/// The letter of part `index` (0-based): A … Z, AA … AZ, BA …, like spreadsheet columns, but without I
/// and O, which read as 1 and 0 beside the numbers.
std::string piece_letter(int index);
/// The inverse of piece_letter (A = 0, … Z = 23, AA = 24, …); -1 for anything that is no part letter.
int letter_rank(const std::string& letter);

/// The label of a seam side: the bare number inside one part; "B12" when the mate is part B on the
/// same sheet; "B12 p3" when the mate is on sheet 3. `mate_letter` empty means the same part;
/// `mate_sheet` (1-based) is 0 when it is on this sheet.
std::string seam_label_text(int number, const std::string& mate_letter, int mate_sheet);

/// A seam's name where it is listed apart from its edges (glue order, JSON): its number after its parts'
/// letters, "A 7" inside part A, "A-B 3" between parts A and B (letters in alphabetical order); the bare
/// number when both letters are empty (a model in one part).
std::string seam_name(int number, const std::string& letter, const std::string& mate_letter);

/// The seam number a label printed by seam_label_text names (0 when it names none): "B12. p3" -> 12.
int seam_number_in(const std::string& label_text);

}  // namespace foldkit::layout
