#include "translate.h"

#include <map>

#include <fmt/format.h>

#include "flatten.h"
#include "stdlib/profile.h"

namespace ncc::translate {
namespace {

// The flattener's trace sink, writing the target text out as it grows.
class Streaming final : public TraceSink {
 public:
  Streaming(Flattener& f, Writer& w, std::FILE* out) : spill(w, out), f_(f) {}
  void event(const Event& e) override {
    f_.event(e);
    spill.grown();
  }

  Spill spill;

 private:
  Flattener& f_;
};

}  // namespace

bool flatten(Session& s, const vm::Module& module, const Request& request, std::FILE* out) {
  const uint32_t errors = s.diags.error_count();
  auto writer = make_writer(request.to, *request.target_profile, s.diags);
  if (!writer) return false;
  MachineConfig target = stdlib::load_machine_config(*request.target_profile, s.diags);
  if (s.diags.error_count() != errors) return false;
  // Each construct once, at its first block, with the count of the others.
  struct Seen {
    uint32_t source;
    Finding kind;
    size_t more = 0;
  };
  std::map<std::string, Seen> seen;
  std::vector<std::string> order;
  Flattener flattener(*writer, module.semantics, target, [&](const Refusal& r) {
    auto [it, fresh] = seen.try_emplace(r.what, Seen{r.source, r.kind});
    if (fresh)
      order.push_back(r.what);
    else if (it->second.source != r.source)
      ++it->second.more;
  });
  if (request.to != "linuxcnc")
    flattener.set_target_power_on(power_on_functions(s, request.to, *request.target_profile));
  writer->begin(request.header);
  Streaming sink(flattener, *writer, out);
  RunSettings run = request.run;
  run.trace_machine_frame = true;
  RunResult result = run_module(s, module, run, sink);
  flattener.finish();
  sink.spill.flush();
  bool refused = false;
  for (const std::string& what : order) {
    const Seen& r = seen.at(what);
    if (r.kind == Finding::RoundedRate) {
      report_at_block(s, module, r.source, DiagId::TranslateRoundedRate,
                      diag_message(DiagId::TranslateRoundedRate, writer->dialect(), what,
                                   writer->rate_decimals(what[0]), rounded_these("value", r.more)));
      continue;
    }
    const std::string text = what + (r.more ? fmt::format(" (and in {} more blocks)", r.more) : "");
    if (r.kind == Finding::Dropped)
      report_at_block(s, module, r.source, DiagId::TranslateDropped,
                      diag_message(DiagId::TranslateDropped, writer->dialect(), text));
    else
      report_at_block(s, module, r.source, DiagId::TranslateRefused,
                      diag_message(DiagId::TranslateRefused, writer->dialect(), text));
    refused |= r.kind == Finding::Refused;
  }
  return result.ok && !result.usage_error && !refused && !sink.spill.failed && s.diags.error_count() == errors;
}

}  // namespace ncc::translate
