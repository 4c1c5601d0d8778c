// The NC-110 dialect as data: the tables of stdlib/dialects/nc110/ and the [nc110]
// settings of the machine profile (docs/profile.md), validated.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contract/program_semantics.h"
#include "contract/services.h"
#include "contract/system_vars.h"
#include "contract/variables.h"
#include "ir/ir.h"
#include "stdlib/profile.h"
#include "stdlib/tables.h"

namespace ncc::nc110 {

// What an operand of a three-letter code is (three_letter_codes.tsv).
enum class OperandKind : uint8_t {
  Origin,
  Axis,
  Dim,
  Pair,
  Angle,
  Factor,
  Count,
  Program,
  Label,
  Comparand,
  Item,
  Seconds,
  Zone,
  Turning,
  Condition,
  Mode,  // UCG's display mode (§2.13.7.1)
  Tool,
  Corrector,
  Increment,
  Distance,
  Speed,  // TOF, RQU, RQP, DPT (§2.13.8-2.13.10)
  Virtual,
  Axes,
  Value,  // UAV (§2.17-2.19)
  Channel,
  Structure,
  Record,
  Records,
  File,
  Access,
  Binding,  // ASSET (chapter 5)
  Prompt,
  Target,
  Field,
  Row,
  Column,
  Format,
  Switch,
  Attribute,  // INP, SCR, DEF, OUT (§5.5, §5.6)
  Process,
  Wait  // EXE, SND, WAI (chapter 4)
};

// A program or device name (§2.13.2.2): lo to hi capitals and digits, a letter first.
inline bool capitals_and_digits(std::string_view s, size_t lo, size_t hi) {
  if (s.size() < lo || s.size() > hi || !(s[0] >= 'A' && s[0] <= 'Z')) return false;
  for (char c : s)
    if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) return false;
  return true;
}

// A device EXE loads a program from (§4.1.1): MP0..MP3.
inline bool exe_device(std::string_view d) {
  return d.size() == 3 && d.starts_with("MP") && d[2] >= '0' && d[2] <= '3';
}

struct OperandItem {
  OperandKind kind = OperandKind::Origin;
  char repeat = '1';      // '1' once, '?' optional, '*' any number, '+' at least one, '~' once, maybe empty
  bool in_group = false;  // inside the signature's optional [...] group
};

// What a three-letter code does: call a runtime function with its operands, or a
// statement of the program's flow.
enum class Action : uint8_t {
  Function,
  Repeat,
  EndRepeat,
  Call,
  CallRange,
  Jump,
  JumpIf,
  Display,
  Asset,
  Input,
  Screen,
  Process
};

struct CodeSignature {
  std::string code;
  std::vector<OperandItem> operands;
  Action action = Action::Function;
  Fn fn = Fn::Count;       // Function
  std::string comparison;  // JumpIf: gt lt eq ne ge le
  // Asset, Screen, Process: the service the code calls, before its operands refine it
  // (OPN W: asset.open_write; OUT with none: screen.show_all).
  Service service = Service::AssetBind;
  std::string meaning;
};

struct SystemName {
  std::string name;              // TMR
  std::optional<SysVar> var;     // none: a keyboard code
  uint32_t first = 0, last = 0;  // the numbers a numbered one takes (TIM0..TIM6)
  bool numbered = false;
  std::string value;  // BY IN LI RE LR flag expr -
};

struct ParameterClass {
  std::string name;  // BY
  uint32_t first = 0;
  VarType type = VarType::LongReal;
  double limit = 0;
};

struct Memory {
  std::string name;  // SA
  MemFormat format = MemFormat::Byte;
  uint32_t bytes = 0;
  bool synchronised = false;  // a block that uses it waits for the motion before it, unless '&' (§2.16)
};

struct Settings {
  stdlib::DialectTables tables;
  std::map<std::string, CodeSignature> codes;
  std::map<std::string, SystemName> system;
  std::vector<ParameterClass> classes;  // by first index
  std::vector<Memory> memories;
  uint32_t e_count = 1000;
  std::string library;  // the program library directory ("" = the program's)
  std::string default_device = "MP0";
  std::vector<std::string> power_on;  // G codes and functions at power-on and reset
  Conventions conventions;

  const ParameterClass& class_of(uint32_t e) const;
};

// Reads the tables and the profile's [nc110] settings; problems are reported at their
// place. Returns nothing if the dialect cannot be used.
[[nodiscard]] std::optional<Settings> load_settings(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::nc110
