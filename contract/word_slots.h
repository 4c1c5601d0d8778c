// Word slots: where each value a block writes travels from the compiler to the
// runtime (BlockWords, the bytecode's `w` operands, the source map). Upper-case
// letters take 0..25 and lower-case ones 26..51 (NC-110 addresses are
// case-sensitive: U and u differ); the operands of a three-letter code take 52..63
// in their written order; a letter's second value takes 64..89: the second R of an
// NC-110 cycle block, the corrector of T1.5, the upper bound of an axis pair; 90 is
// pp's '&'.
#pragma once

#include <string>

namespace ncc {

constexpr int kWordSlots = 96;
constexpr int kOperandSlots = 12;

constexpr int letter_slot(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return 26 + (c - 'a');
  return -1;
}
constexpr int operand_slot(int i) { return i >= 0 && i < kOperandSlots ? 52 + i : -1; }
constexpr int second_slot(char c) { return c >= 'A' && c <= 'Z' ? 64 + (c - 'A') : -1; }
// pp '&': the length-compensation link, four digits for the axes of Conventions::link_axes.
constexpr int kLinkSlot = 90;

// "X", "u", "#3" (the third operand), "R'" (the second R).
inline std::string slot_name(int slot) {
  if (slot >= 0 && slot < 26) return std::string(1, static_cast<char>('A' + slot));
  if (slot >= 26 && slot < 52) return std::string(1, static_cast<char>('a' + slot - 26));
  if (slot >= 52 && slot < 64) return "#" + std::to_string(slot - 51);
  if (slot >= 64 && slot < 90) return std::string(1, static_cast<char>('A' + slot - 64)) + "'";
  if (slot == kLinkSlot) return "&";
  return "?";
}

// For messages: "X", "operand 3", "the second R".
inline std::string slot_text(int slot) {
  if (slot >= 52 && slot < 64) return "operand " + std::to_string(slot - 51);
  if (slot >= 64 && slot < 90) return std::string("the second ") + static_cast<char>('A' + slot - 64);
  return slot_name(slot);
}

}  // namespace ncc
