#include "foldkit/layout/label_text.hpp"

#include <algorithm>
#include <string_view>

namespace foldkit::layout {

bool reads_as_other_number_turned(int number) {
  if (number < 0) return false;
  const std::string digits = std::to_string(number);
  std::string turned;
  for (auto it = digits.rbegin(); it != digits.rend(); ++it) {
    switch (*it) {
      case '0':
      case '1':
      case '8':
        turned.push_back(*it);
        break;
      case '6':
        turned.push_back('9');
        break;
      case '9':
        turned.push_back('6');
        break;
      default:
        return false;  // 2 3 4 5 7 turned are no digits: the number reads as nothing else
    }
  }
  return turned != digits && turned.front() != '0';
}

std::string number_text(int number) {
  std::string text = std::to_string(number);
  if (reads_as_other_number_turned(number)) text.push_back('.');
  return text;
}

namespace {
// No I or O: beside a seam number ("I 135", "O 10") they read as the digits 1 and 0.
constexpr std::string_view kLetters = "ABCDEFGHJKLMNPQRSTUVWXYZ";
constexpr int kMaxLetters = 6;  // 24^6 parts: far beyond any sheet, and no int overflow below
}  // namespace

std::string piece_letter(int index) {
  const int base = static_cast<int>(kLetters.size());
  std::string letters;
  for (int n = index + 1; n > 0; n = (n - 1) / base)
    letters.push_back(kLetters[(n - 1) % base]);
  std::reverse(letters.begin(), letters.end());
  return letters;
}

int letter_rank(const std::string& letter) {
  if (letter.empty() || letter.size() > kMaxLetters) return -1;
  const int base = static_cast<int>(kLetters.size());
  int rank = 0;
  for (char c : letter) {
    const std::size_t digit = kLetters.find(c);
    if (digit == std::string_view::npos) return -1;
    rank = base * rank + static_cast<int>(digit) + 1;
  }
  return rank - 1;
}

std::string seam_label_text(int number, const std::string& mate_letter, int mate_sheet) {
  // "B12" rather than "B 12": a space costs most of a digit's width, and on a small face that decides
  // whether the label fits clear of the fold lines. The letter cannot be read as a digit (no I or O).
  std::string text = mate_letter + number_text(number);
  if (!mate_letter.empty() && mate_sheet > 0) text.append(" p").append(std::to_string(mate_sheet));
  return text;
}

std::string seam_name(int number, const std::string& letter, const std::string& mate_letter) {
  if (letter.empty() && mate_letter.empty()) return number_text(number);
  if (letter == mate_letter || mate_letter.empty()) return letter + " " + number_text(number);
  if (letter.empty()) return mate_letter + " " + number_text(number);
  const bool in_order = letter_rank(letter) <= letter_rank(mate_letter);
  return (in_order ? letter : mate_letter) + "-" + (in_order ? mate_letter : letter) + " " +
         number_text(number);
}

int seam_number_in(const std::string& text) {
  // The number is the first run of digits: the mate's letter comes before it, the sheet after it.
  const std::size_t i = text.find_first_of("0123456789");
  if (i == std::string::npos) return 0;
  int n = 0;
  for (std::size_t j = i; j < text.size() && text[j] >= '0' && text[j] <= '9' && n < 100000000; ++j)
    n = 10 * n + (text[j] - '0');
  return n;
}

}  // namespace foldkit::layout
