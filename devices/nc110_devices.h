// The NC-110 controller's devices as a program's services reach them
// (contract/services.h): a process's ASSET channels and record structures (chapter 5),
// the operator's answers to INP (§5.5) and the user screen (§5.6). Each process has
// its own; what the processes of a run share (the screen, the files open, the answers
// taken) is the run's, Nc110Run.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asset_channels.h"
#include "contract/services.h"
#include "user_screen.h"

namespace ncc::devices {

// The operator's answer to INP: a number, a text, or neither: ENTER, the value offered
// stays.
struct Answer {
  std::optional<double> number;
  std::optional<std::string> text;
};

// What the processes of a run share (NC-110 §4.1.3): the user screen (one video frame
// 8), the ASSET files, the operator's answers.
struct Nc110Run {
  screen::UserScreen screen;
  // The ASSET statements act (a real run): a process's channels are its own, the files
  // open are the run's. Else (a dry run) they have no effect: the files are the
  // machine's, not the program's.
  bool files = false;
  asset::Store* store = nullptr;  // none: ASSET is not configured (every statement: code 18)
  asset::Channels::Settings channels = {};
  asset::OpenFiles open_files;
  // The operator's answers to INP, in order, and how many are taken; none: a dry run,
  // every answer is the value offered.
  const std::vector<Answer>* answers = nullptr;
  size_t answered = 0;
};

// One process's devices: the services of the asset, input and screen devices.
class Nc110Devices final : public ServiceHost {
 public:
  explicit Nc110Devices(Nc110Run& run);
  ServiceResult call(Service service, ServiceCall& call) override;

 private:
  // A variable a record structure binds (DER).
  struct AssetField {
    uint8_t space;
    bool memory;
    MemFormat format;  // memory
    uint8_t chars;     // memory: a text of this many bytes (0: a value of `format`)
    uint32_t index;    // variable index, or memory index (bytes for a text)
  };
  // Each false when the run stops (reported).
  bool asset(Service service, ServiceCall& call);
  bool asset_values(ServiceCall& call, const std::vector<AssetField>& fields, std::vector<asset::Value>& out);
  bool asset_store(ServiceCall& call, const std::vector<AssetField>& fields, const std::vector<asset::Value>& values);
  bool input(Service service, ServiceCall& call);
  // SCR, DEF, OUT: the fields a statement showed go to the trace.
  bool user_screen(Service service, ServiceCall& call);
  bool field_content(Service service, ServiceCall& call, screen::Content& c);

  Nc110Run& run_;
  std::unique_ptr<asset::Channels> channels_;  // none: a dry run
  std::vector<AssetField> fields_;             // of the structure being defined
  std::map<uint32_t, std::vector<AssetField>> structures_;
};

}  // namespace ncc::devices
