#include "isolated_row.hpp"

#include <algorithm>

#include "device_wait.hpp"
#include "errors.hpp"
#include "grid.hpp"

namespace pxflow {
namespace {

using worker::Clock;
using worker::Reply;

Clock::time_point after(double seconds) {
  return Clock::now() +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

IsolatedRow::IsolatedRow(std::string row, const IsolationOptions& options)
    : row_(std::move(row)), options_(options) {}

void IsolatedRow::start() {
  std::vector<std::string> argv = options_.worker_command;
  argv.push_back(worker::kWorkerOption);
  argv.push_back(row_);
  worker_ = std::make_unique<worker::WorkerProcess>(argv);
}

IsolatedRow::Opened IsolatedRow::opened() {
  Opened o;
  Reply gone;
  const std::optional<worker::Hello> h = worker_->hello(after(kOpenSeconds), gone);
  if (!h) {
    o.failed = true;
    o.why = "its check worker " +
            (gone.kind == Reply::Kind::kTimedOut
                 ? "did not open the backend within " + setting_text(kOpenSeconds) + " s"
                 : gone.text + " while opening the backend");
    worker_.reset();
    return o;
  }
  if (h->state == worker::Hello::State::kInputError) throw InputError(h->why);
  o.ok = h->state == worker::Hello::State::kOpened;
  o.why = h->why;
  o.implementation = h->implementation;
  o.device = h->device;
  if (!o.ok) worker_.reset();
  return o;
}

bool IsolatedRow::restart(std::string& why) {
  try {
    start();
    const Opened o = opened();
    if (o.ok) return true;
    why = o.why;
  } catch (const SpawnError& e) {
    why = e.what();
  } catch (const InputError& e) {
    why = e.what();
  }
  worker_.reset();
  return false;
}

std::string IsolatedRow::unsupported(const Params& p) {
  if (!worker_) return "its check worker is not running";
  const Reply r = worker_->run(p, {}, after(kOpenSeconds));
  if (r.kind == Reply::Kind::kNotApplicable) return r.text;
  return "its check worker did not answer whether it supports these parameters";
}

bool IsolatedRow::outside_limits(const Params& p) {
  if (dead_ || !worker_) return false;
  const Reply r = worker_->run(p, {}, after(kOpenSeconds));
  if (r.kind != Reply::Kind::kNotApplicable) worker_.reset();  // restarted by the next run()
  return r.kind == Reply::Kind::kNotApplicable && !r.text.empty();
}

IsolatedRow::PairsRun IsolatedRow::run_pairs(std::span<const FramePair> pairs, const Params& p) {
  if (!worker_) return {{}, "its check worker is not running"};
  if (const Reply b = prepare(p); b.kind != Reply::Kind::kDone)
    return {{},
            b.kind == Reply::Kind::kNotApplicable ? "n/a: " + b.text
                                                  : "building its kernels: " + b.text};
  const Reply r = worker_->run(p, pairs, after(allowance(p, pairs.size(), 1.0)));
  switch (r.kind) {
    case Reply::Kind::kDone:
      if (!r.done.guard_note.empty()) return {{}, r.done.guard_note};
      return {r.done.records, {}};
    case Reply::Kind::kNotApplicable:
      return {{}, "n/a: " + r.text};
    case Reply::Kind::kTimedOut:
      worker_.reset();
      return {{}, "did not finish"};
    default:
      if (r.kind != Reply::Kind::kError) worker_.reset();
      return {{}, r.text.empty() ? "its worker ended" : r.text};
  }
}

double IsolatedRow::allowance(const Params& p, std::size_t pairs, double reference_seconds) const {
  if (options_.case_timeout > 0) return options_.case_timeout;
  const DeviceWork work{pairs, poi_count(p), p.search_radius};
  const double ratio = worst_ratio_ < 0 ? kFirstRatio : worst_ratio_;
  return 2 * device_timeout_seconds() * work_units(work) + kSlowMargin * ratio * reference_seconds;
}

IsolatedRow::CaseRun IsolatedRow::run(const CheckCase& c, long index, double reference_seconds) {
  CaseRun out;
  std::string why;
  if (dead_ || (!worker_ && !restart(why))) {
    out.not_run = true;
    if (!dead_)
      out.failure = "its check worker could not be restarted (" + why +
                    "): the row's remaining cases were not run";
    dead_ = true;
    return out;
  }
  const std::string which = "case " + std::to_string(index) + " " + quoted(c.name);
  if (!built(c.params, which, out)) return out;
  std::vector<FramePair> views;
  for (const auto& p : c.pairs) views.push_back(p.view());
  const double allowed = allowance(c.params, views.size(), reference_seconds);
  Reply r = worker_->run(c.params, views, after(allowed));
  switch (r.kind) {
    case Reply::Kind::kNotApplicable:
      out.not_applicable = true;
      return out;
    case Reply::Kind::kError:
      out.failure = "error: " + r.text;
      return out;
    case Reply::Kind::kTimedOut:
      worker_.reset();
      out.failure = "did not finish " + which + " within " + setting_text(allowed) + " s" +
                    (options_.case_timeout > 0 ? " (--case-timeout)"
                                               : " (its allowance; --case-timeout sets another)");
      return out;
    case Reply::Kind::kDied: {
      worker_.reset();
      std::string note;
      std::size_t pair = 0;
      if (r.fault && r.fault->where != worker::Fault::kElsewhere) {
        pair = r.fault->pair;
        note = worker::fault_text(*r.fault, "the pair");
      }
      std::string where = " in " + which;
      if (c.pairs.size() > 1 && note.empty()) {
        where += locate_crash(c, reference_seconds, note);
      } else {
        where += " pair " + std::to_string(pair) + " " + quoted(c.pairs[pair].name);
      }
      out.failure = r.text + where + (note.empty() ? "" : ": " + note);
      return out;
    }
    case Reply::Kind::kDone:
      break;
  }
  if (!r.done.guard_note.empty()) {
    out.failure = r.done.guard_note;
    return out;
  }
  out.records = std::move(r.done.records);
  out.counts = r.done.counts;
  out.seconds = r.done.seconds;
  worst_ratio_ = std::max(worst_ratio_, out.seconds / std::max(reference_seconds, 1e-6));
  return out;
}

Reply IsolatedRow::prepare(const Params& p) {
  Reply b = worker_->prepare(p, after(kPrepareSeconds));
  if (b.kind == Reply::Kind::kDied || b.kind == Reply::Kind::kTimedOut) worker_.reset();
  return b;
}

bool IsolatedRow::built(const Params& p, const std::string& which, CaseRun& out) {
  const Reply b = prepare(p);
  switch (b.kind) {
    case Reply::Kind::kDone:
      out.build_seconds = b.done.seconds;
      return true;
    case Reply::Kind::kNotApplicable:
      out.not_applicable = true;
      return false;
    case Reply::Kind::kError:
      out.failure = "error: " + b.text;
      return false;
    case Reply::Kind::kTimedOut:
      out.failure = "did not build its kernels for " + which + " within " +
                    setting_text(kPrepareSeconds) +
                    " s (a build's allowance, apart from the case's)";
      return false;
    case Reply::Kind::kDied:
      break;
  }
  out.failure = b.text + " while building its kernels for " + which;
  return false;
}

// Runs the case's pairs one at a time in a fresh worker until one ends it: " pair N 'name'".
std::string IsolatedRow::locate_crash(const CheckCase& c, double reference_seconds,
                                      std::string& note) {
  const double per_pair = reference_seconds / static_cast<double>(c.pairs.size());
  std::string why;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    if (!worker_ && !restart(why)) return " (its worker could not be restarted to find the pair)";
    if (const Reply b = prepare(c.params);
        b.kind == Reply::Kind::kDied || b.kind == Reply::Kind::kTimedOut)
      return " (its worker ended while building its kernels, before pair " + std::to_string(i) +
             ")";
    const FramePair one[] = {c.pairs[i].view()};
    const Reply r = worker_->run(c.params, one, after(allowance(c.params, 1, per_pair)));
    if (r.kind != Reply::Kind::kDied && r.kind != Reply::Kind::kTimedOut) continue;
    worker_.reset();
    if (r.fault) note = worker::fault_text(*r.fault, "the pair");
    return " pair " + std::to_string(i) + " " + quoted(c.pairs[i].name);
  }
  worker_.reset();
  return " (no pair of it ends the worker alone)";
}

}  // namespace pxflow
