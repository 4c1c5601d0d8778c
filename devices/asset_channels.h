// What the ASSET statements of one process do (NC-110 §5.3): its channels, each
// with a file open on it and a record pointer, and its record structures. Every
// statement answers with the code of table 5.2 that IOSTA takes (ERR=1) or that
// stops the run (ERR=0); when several apply, the first in the order of
// docs/asset.md, "Statements". The variables a structure binds are the VM's: a
// record goes in and out as one value a field.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "asset_store.h"

namespace ncc::asset {

// Who has which file open, over every process: a file open for writing is open
// nowhere else (§5.3.2.1, code 7).
class OpenFiles {
 public:
  bool can_open(const FileName& name, bool write) const;
  bool is_open(const FileName& name) const { return open_.count(name.text()) > 0; }
  void opened(const FileName& name, bool write);
  void closed(const FileName& name, bool write);

 private:
  struct Opens {
    uint32_t readers = 0;
    bool writer = false;
  };
  std::map<std::string, Opens> open_;
};

// A field's value in a record going in or out.
struct Value {
  double number = 0;
  std::string chars;  // a CH field's characters
  bool operator==(const Value&) const = default;
};

class Channels {
 public:
  struct Settings {
    uint32_t channels = 8;     // PGCFIL CHN: channels 1..channels
    uint32_t structures = 16;  // PGCFIL STR: structures 1..structures
    uint8_t default_device = 1;
  };
  // `store` null: ASSET is not configured (every statement: code 18).
  Channels(Store* store, OpenFiles& open_files, const Settings& settings);
  ~Channels();
  Channels(const Channels&) = delete;
  Channels& operator=(const Channels&) = delete;

  const Settings& settings() const { return settings_; }
  // DER: false when `structure` is not 1..structures or the layout is not one.
  [[nodiscard]] bool define(uint32_t structure, const Layout& layout);
  Code open(uint32_t channel, const FileName& name, bool write);  // OPN
  // RED and WRT; `at`, when given, takes the record they went to.
  Code read(uint32_t channel, uint32_t structure, std::optional<uint32_t> record, std::vector<Value>& out,
            uint32_t* at = nullptr);
  Code write(uint32_t channel, uint32_t structure, std::optional<uint32_t> record, const std::vector<Value>& values,
             uint32_t* at = nullptr);
  Code close(uint32_t channel);                                             // CLO n
  Code close_all();                                                         // CLO
  Code create(uint32_t structure, const FileName& name, uint32_t records);  // CRE
  Code remove(const FileName& name);                                        // CAN

 private:
  struct Open {
    FileName name;
    bool write = false;
    File file;          // as it is on the device
    uint32_t next = 1;  // the record a RED or WRT without a number takes
  };
  Code channel_file(uint32_t channel, Open*& open);
  Code record_of(const Open& open, std::optional<uint32_t> record, uint32_t& r) const;

  Store* store_;
  OpenFiles& open_files_;
  Settings settings_;
  std::map<uint32_t, Open> channels_;
  std::map<uint32_t, Layout> structures_;
};

}  // namespace ncc::asset
