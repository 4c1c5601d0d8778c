#include "nc110_devices.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "support/numbers.h"
#include "support/text.h"

namespace ncc::devices {

namespace {

// An operand numbering something 1..hi (an ASSET channel, structure or record, a
// screen field): the number, or 0, which numbers nothing (so the statement answers
// with its code or error).
uint32_t whole_operand(double v, uint32_t hi) { return whole_in<uint32_t>(v, 1, hi).value_or(0); }

}  // namespace

Nc110Devices::Nc110Devices(Nc110Run& run) : run_(run) {
  if (run_.files) channels_ = std::make_unique<asset::Channels>(run_.store, run_.open_files, run_.channels);
}

ServiceResult Nc110Devices::call(Service service, ServiceCall& call) {
  bool ok = false;
  switch (service_info(service).device) {
    case Device::Asset: ok = asset(service, call); break;
    case Device::Input: ok = input(service, call); break;
    case Device::Screen: ok = user_screen(service, call); break;
    default:
      ok = call.fail(DiagId::BytecodeInvalid, "program",
                     fmt::format("{}: not a service of the NC-110 devices", service_info(service).name));
  }
  return ok ? ServiceResult::Done : ServiceResult::Error;
}

// ---- ASSET files (NC-110 chapter 5) ----------------------------------------------------

bool Nc110Devices::asset_values(ServiceCall& call, const std::vector<AssetField>& fields,
                                std::vector<asset::Value>& out) {
  out.clear();
  for (const AssetField& f : fields) {
    asset::Value v;
    bool ok = true;
    if (!f.memory) {
      ok = call.load(f.space, f.index, v.number);
    } else if (f.chars) {
      const uint8_t* b = call.bytes(f.space, f.index, f.chars);
      if (!b) return false;
      v.chars.assign(reinterpret_cast<const char*>(b), f.chars);
    } else {
      ok = call.load_mem(f.space, f.format, f.index, v.number);
    }
    if (!ok) return false;
    out.push_back(std::move(v));
  }
  return true;
}

bool Nc110Devices::asset_store(ServiceCall& call, const std::vector<AssetField>& fields,
                               const std::vector<asset::Value>& values) {
  for (size_t i = 0; i < fields.size() && i < values.size(); ++i) {
    const AssetField& f = fields[i];
    if (!f.memory) {
      if (!call.store(f.space, f.index, values[i].number)) return false;
    } else if (f.chars) {
      uint8_t* b = call.bytes(f.space, f.index, f.chars);
      if (!b) return false;
      std::memcpy(b, values[i].chars.data(), std::min<size_t>(f.chars, values[i].chars.size()));
      call.wrote_memory();
    } else if (!call.store_mem(f.space, f.format, f.index, values[i].number)) {
      return false;
    }
  }
  return true;
}

bool Nc110Devices::asset(Service service, ServiceCall& call) {
  auto stop = [&]<typename... Args>(DiagIdFor<Args...> id, const Args&... args) {  // the run stops
    return call.fail(id, args...);
  };
  auto file_text = [&]() -> const std::string& { return call.string(call.operand(0)); };
  auto file = [&] { return asset::parse_file_name(file_text(), 1); };
  // Building a structure (DER): its fields, in order.
  if (service == Service::AssetBind || service == Service::AssetBindMem || service == Service::AssetBindText) {
    AssetField f{static_cast<uint8_t>(call.operand(0)), service != Service::AssetBind, MemFormat::Byte, 0, 0};
    if (service == Service::AssetBind) f.index = call.operand(1);
    if (service == Service::AssetBindMem) f.format = static_cast<MemFormat>(call.operand(1));
    if (service == Service::AssetBindText) f.chars = static_cast<uint8_t>(call.operand(1));
    if (f.memory) {
      const double index = call.pop();
      const VarSpace& space = call.space(f.space);
      const uint32_t size = space.size;
      const std::optional<uint32_t> i = size ? whole_in<uint32_t>(index, 0, size - 1) : std::nullopt;
      if (!i) return stop(DiagId::MemoryRange, space.name, shortest(index), f.chars ? f.chars : 1, size);
      f.index = *i;
    }
    fields_.push_back(f);
    return true;
  }
  if (service == Service::AssetDefine) {
    const double number = call.pop();
    std::vector<AssetField> fields = std::exchange(fields_, {});
    asset::Layout layout;
    for (const AssetField& f : fields) {
      // A field has the variable's format (table 5.1): IN, RE, LR or kCH, nothing else.
      const VarType t = f.memory ? VarType::Count : call.type_of(f.space, f.index);
      const bool in = f.memory ? f.format == MemFormat::Integer : t == VarType::Integer;
      const bool re = f.memory ? f.format == MemFormat::Real : t == VarType::Real;
      const bool lr = f.memory ? f.format == MemFormat::LongReal : t == VarType::LongReal;
      if (f.chars)
        layout.push_back({asset::FieldType::Chars, f.chars});
      else if (in || re || lr)
        layout.push_back(*asset::parse_field(in ? "IN" : re ? "RE" : "LR"));
      else
        return stop(DiagId::AssetStructure, shortest(number), "a variable has no ASSET format (IN, RE, LR, kCH)");
    }
    if (!channels_) return true;  // a dry run
    const uint32_t s = whole_operand(number, channels_->settings().structures);
    if (!channels_->define(s, layout))
      return stop(DiagId::AssetStructure, shortest(number),
                  fmt::format("structures are 1..{} and hold 1..{} fields", channels_->settings().structures,
                              asset::kMaxFields));
    structures_[s] = std::move(fields);
    return true;
  }
  // The I/O statements: their operands, what they did, and the code (§5.4).
  double record = 0, second = 0, first = 0;
  if (service == Service::AssetReadAt || service == Service::AssetWriteAt) record = call.pop();
  if (service == Service::AssetRead || service == Service::AssetReadAt || service == Service::AssetWrite ||
      service == Service::AssetWriteAt || service == Service::AssetCreate)
    second = call.pop();
  if (service != Service::AssetCloseAll && service != Service::AssetDelete) first = call.pop();
  if (!channels_) return true;  // a dry run: files are the machine's, not the program's
  asset::Channels& io = *channels_;
  std::string what;
  asset::Code code = asset::Code::Ok;
  switch (service) {
    case Service::AssetOpen:
    case Service::AssetOpenWrite: {
      const bool write = service == Service::AssetOpenWrite;
      auto name = file();
      what = fmt::format("open {} {} {}", shortest(first), file_text(), write ? "W" : "R");
      code = name ? io.open(whole_operand(first, 255), *name, write) : asset::Code::NotFound;
      break;
    }
    case Service::AssetRead:
    case Service::AssetReadAt:
    case Service::AssetWrite:
    case Service::AssetWriteAt: {
      const bool reading = service == Service::AssetRead || service == Service::AssetReadAt;
      const bool given = service == Service::AssetReadAt || service == Service::AssetWriteAt;
      const uint32_t s = whole_operand(second, 255);
      std::optional<uint32_t> r;
      if (given) r = whole_operand(record, asset::kMaxRecords);
      uint32_t at = 0;
      std::vector<asset::Value> values;
      auto fields = structures_.find(s);
      if (reading) {
        code = io.read(whole_operand(first, 255), s, r, values, &at);
        if (code == asset::Code::Ok && fields != structures_.end() && !asset_store(call, fields->second, values))
          return false;
      } else {
        if (fields != structures_.end() && !asset_values(call, fields->second, values)) return false;
        code = io.write(whole_operand(first, 255), s, r, values, &at);
      }
      what = fmt::format("{} {} structure {} record {}", reading ? "read" : "write", shortest(first), shortest(second),
                         at      ? std::to_string(at)
                         : given ? shortest(record)
                                 : std::string("next"));
      break;
    }
    case Service::AssetClose:
      what = fmt::format("close {}", shortest(first));
      code = io.close(whole_operand(first, 255));
      break;
    case Service::AssetCloseAll:
      what = "close all";
      code = io.close_all();
      break;
    case Service::AssetCreate: {
      auto name = file();
      what = fmt::format("create {} structure {} records {}", file_text(), shortest(first), shortest(second));
      code = name ? io.create(whole_operand(first, 255), *name, whole_operand(second, asset::kMaxRecords))
                  : asset::Code::Illegal;
      break;
    }
    case Service::AssetDelete: {
      auto name = file();
      what = fmt::format("delete {}", file_text());
      code = name ? io.remove(*name) : asset::Code::NotFound;
      break;
    }
    default: break;
  }
  if (!call.machine().asset_done(what, static_cast<int>(code), call.block()))
    return stop(DiagId::AssetError, what, static_cast<int>(code),
                code == asset::Code::NotConfigured ? "ASSET area not configured (ncc run --files DIR gives one)"
                                                   : asset::meaning(code));
  return true;
}

// ---- Operator input (NC-110 §5.5) ------------------------------------------------------

// INP: the cycle stops until the operator answers; ENTER keeps the value offered. A run
// reads the answers of --input, in order; a dry run keeps every value.
bool Nc110Devices::input(Service service, ServiceCall& call) {
  const bool text = service == Service::InputText || service == Service::InputFieldText;
  const auto chars = static_cast<uint8_t>(text ? call.operand(1) : 0);
  const double index = text ? call.pop() : 0;
  uint8_t* memory = text ? call.bytes(static_cast<uint8_t>(call.operand(0)), index, chars) : nullptr;
  if (text && !memory) return false;
  const double offered = text ? 0 : call.pop();
  std::string prompt;
  if (service == Service::InputField || service == Service::InputFieldText) {
    const double field = call.pop();
    auto shown = run_.screen.text(whole_operand(field, 255));
    if (!shown)
      return call.fail(DiagId::ScreenError,
                       fmt::format("(INP) takes its prompt from field {}, which holds no text", shortest(field)));
    prompt = *shown;
  } else {
    prompt = call.string(call.operand(text ? 2 : 0));
  }
  Answer answer;
  if (run_.answers) {
    if (run_.answered >= run_.answers->size()) return call.fail(DiagId::InputExhausted, run_.answered);
    answer = (*run_.answers)[run_.answered++];
  }
  if (!text) {
    if (answer.text) return call.fail(DiagId::InputAnswer, fmt::format("\"{}\"", *answer.text), "a text", "a number");
    call.machine().operator_input(prompt + shortest(offered), answer.number.value_or(offered), call.block());
    call.push(answer.number.value_or(offered));
    return true;
  }
  std::string now(reinterpret_cast<const char*>(memory), chars);
  std::string shown = now;
  std::replace(shown.begin(), shown.end(), '\0', ' ');  // memory never written holds zeros
  if (answer.number) return call.fail(DiagId::InputAnswer, shortest(*answer.number), "a number", "a text in quotes");
  std::string typed = answer.text.value_or(now);
  if (typed.size() > chars)
    return call.fail(DiagId::InputAnswer, fmt::format("\"{}\"", typed), fmt::format("{} bytes long", typed.size()),
                     fmt::format("a text of at most {} bytes", chars));
  typed.resize(chars, ' ');  // the rest of the field blank
  call.machine().operator_input(prompt + shown, typed, call.block());
  std::copy(typed.begin(), typed.end(), memory);
  call.wrote_memory();
  return true;
}

// ---- The user screen (NC-110 §5.6) -------------------------------------------------------

// What DEF or OUT gives a field: strings[s], a text in memory (operands v n, its byte
// index popped) or a value popped.
bool Nc110Devices::field_content(Service service, ServiceCall& call, screen::Content& c) {
  const bool string = service == Service::ScreenDefineText || service == Service::ScreenShowText;
  const bool memory = service == Service::ScreenDefineMem || service == Service::ScreenShowMem;
  c.is_text = string || memory;
  if (string) c.text = call.string(call.operand(0));
  if (!memory) {
    if (!string) c.value = call.pop();
    return true;
  }
  const auto chars = static_cast<uint8_t>(call.operand(1));
  const uint8_t* b = call.bytes(static_cast<uint8_t>(call.operand(0)), call.pop(), chars);
  if (b) c.text.assign(reinterpret_cast<const char*>(b), chars);
  return b != nullptr;
}

bool Nc110Devices::user_screen(Service service, ServiceCall& call) {
  screen::UserScreen& screen = run_.screen;
  const uint32_t source = call.block();
  std::string why;
  switch (service) {
    case Service::ScreenOn:
      screen.switch_on();
      call.machine().screen_event("on", source);
      return true;
    case Service::ScreenOff:
      screen.switch_off();
      call.machine().screen_event("off", source);
      return true;
    case Service::ScreenDefineText:
    case Service::ScreenDefineMem:
    case Service::ScreenDefineValue: {
      screen::Content init;
      if (!field_content(service, call, init)) return false;
      const double attribute = call.pop(), format = call.pop(), column = call.pop(), row = call.pop(),
                   field = call.pop();
      std::optional<screen::Format> f;
      if (auto n = whole_in(format, 1, 7))
        f = static_cast<screen::Format>(*n);
      else if (format != 0)
        why = fmt::format("format {} is not one: 1 to 7 (BL BY IN LI RE LR CH)", shortest(format));
      screen::Attributes a{attribute == 256, whole_in(attribute, 0, 255).value_or(-1)};
      // A row or column that is no whole number of six digits is 0, which define() refuses.
      const auto place = [](double v) { return whole_in<int>(v, -999999, 999999).value_or(0); };
      if (why.empty()) why = screen.define(whole_operand(field, 255), place(row), place(column), init, f, a);
      break;
    }
    case Service::ScreenShow: {
      const double field = call.pop();
      why = screen.show(whole_operand(std::fabs(field), 255), field < 0);
      break;
    }
    case Service::ScreenShowAll: why = screen.show_all(); break;
    case Service::ScreenShowValue:
    case Service::ScreenShowText:
    case Service::ScreenShowMem: {
      screen::Content c;
      if (!field_content(service, call, c)) return false;
      why = screen.show_with(whole_operand(call.pop(), 255), c);
      break;
    }
    default: break;
  }
  if (!why.empty()) return call.fail(DiagId::ScreenError, why);
  for (uint32_t n : screen.take_shown()) {
    const screen::Attributes a = screen.attributes(n);
    std::string text =
        fmt::format("field {} row {} column {} \"{}\"", n, screen.row(n), screen.column(n), screen.rendered(n));
    if (a.inverse) text += " inverse";
    if (a.colour >= 0) text += fmt::format(" colour {}", a.colour);
    call.machine().screen_event(text, source);
  }
  return true;
}

}  // namespace ncc::devices
