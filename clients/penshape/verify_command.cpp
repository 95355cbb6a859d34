// `penshape verify FILE ANSWER.json [--json]`: re-checks what `deconstruct --json` printed, with
// the independent exact verifier of penshape/core/verify.hpp.
#include "verify_command.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "geometry_cli.hpp"
#include "json_value.hpp"
#include "json_writer.hpp"
#include "penshape/core/verify.hpp"
#include "stroke_files.hpp"
#include "verify_answer.hpp"
#include "verify_recognition_answer.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape verify FILE ANSWER.json [--json]\n\n"
    "Re-checks the answers `penshape deconstruct FILE ... --json` printed (one object, or JSON\n"
    "lines, one per answer), independently of the engines and exactly (interval arithmetic with\n"
    "an exact rational fallback; offsets with true arcs). r, eps and delta are read from each\n"
    "answer (its \"exact\" object when present).\n"
    "  YES: P is a valid region and H(offset(P, r), FILE) <= eps.\n"
    "  NO: the witness is a point of FILE that no valid P can serve.\n"
    "  UNDECIDED: claims nothing; accepted.\n"
    "Prints `verified` or what fails and where (refuted: a counterexample point; unproven: the\n"
    "proof did not close near a point). With several answers each line is `answer N: ...`.\n"
    "--json prints one object per answer: answer, status (verified|refuted|unproven), verified,\n"
    "message, cells.\n"
    "Exit codes: 0 every answer verified, 1 some answer not verified, 2 bad input.\n\n"
    "Recognition answers: FILE is the stroke file `penshape recognize FILE --json` read and\n"
    "ANSWER.json what it printed (one object per shape or group; the strokes are found by\n"
    "\"lines\"). eps, r and the bound come from each answer's certificate: the claim is\n"
    "H(inks) <= bound <= eps, so a bound above eps is refuted. The clean shape is rebuilt from\n"
    "its class and params (curves as chord polylines with a derived deviation; a curved arrow\n"
    "shaft as the 12 chords that were certified) and the paths are proven within the bound of\n"
    "each other (which bounds the inks, r-disks on both, by the same): refuted names a point of\n"
    "one ink farther than the bound from the other; unproven says where the paths are not within\n"
    "it. Freeform answers claim nothing and are accepted.";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One verdict: a JSON object (the claim's own keys first, written by `claim_keys`) or a text
// line naming the claim (`what`) unless it is verified.
template <typename ClaimKeys>
void print_verdict(const VerifyReport& rep, const std::string& what, std::size_t index,
                   std::size_t count, bool as_json, ClaimKeys&& claim_keys) {
  if (as_json) {
    JsonWriter json;
    json.begin_object();
    claim_keys(json);
    json.key("status").string(to_string(rep.status));
    json.key("verified").boolean(rep.status == VerifyStatus::kVerified);
    json.key("message").string(rep.message);
    json.key("cells").integer(static_cast<std::int64_t>(rep.cells));
    json.end_object();
    std::puts(json.str().c_str());
    return;
  }
  std::string line = count > 1 ? "answer " + std::to_string(index + 1) + ": " : std::string();
  if (rep.status == VerifyStatus::kVerified) {
    line += rep.message;
  } else {
    line += what + " " + to_string(rep.status) + ": " + rep.message;
  }
  std::puts(line.c_str());
}

void print(const VerifyReport& rep, const DeconstructionClaim& claim, std::size_t index,
           std::size_t count, bool as_json) {
  print_verdict(rep, to_string(claim.answer), index, count, as_json,
                [&](JsonWriter& json) { json.key("answer").string(to_string(claim.answer)); });
}

// The strokes an answer covers, by their lines in the stroke file.
std::vector<std::vector<PointD>> strokes_of(const std::vector<FileStroke>& file,
                                            const RecognitionAnswer& a) {
  std::vector<std::vector<PointD>> out;
  for (const std::size_t line : a.lines) {
    const auto it =
        std::find_if(file.begin(), file.end(), [&](const FileStroke& s) { return s.line == line; });
    if (it == file.end()) throw InputError("no stroke at line " + std::to_string(line));
    std::vector<PointD> points;
    for (const StrokePoint& p : it->points) points.push_back({p.x, p.y});
    out.push_back(std::move(points));
  }
  return out;
}

void print_recognition(const VerifyReport& rep, const RecognitionAnswer& a, std::size_t index,
                       std::size_t count, bool as_json) {
  const std::string what =
      "line " + std::to_string(a.lines.front()) + " " + to_string(a.claim.shape);
  print_verdict(rep, what, index, count, as_json, [&](JsonWriter& json) {
    json.key("line").integer(static_cast<std::int64_t>(a.lines.front()));
    json.key("class").string(to_string(a.claim.shape));
  });
}

// Checks the answers 0..count-1 in turn and prints each: exit 0 when all are verified, 1 when
// one is not, 2 (naming the answer) at the first that is not a valid claim.
int check_each(const std::string& answer_path, std::size_t count,
               const std::function<VerifyReport(std::size_t)>& check,
               const std::function<void(const VerifyReport&, std::size_t)>& print_one) {
  bool all = true;
  for (std::size_t i = 0; i < count; ++i) {
    VerifyReport rep;
    try {
      rep = check(i);
    } catch (const InvalidInput& e) {
      std::fprintf(stderr, "penshape verify: %s: answer %zu: %s\n", answer_path.c_str(), i + 1,
                   e.what());
      return kExitBadInput;
    }
    all = all && rep.status == VerifyStatus::kVerified;
    print_one(rep, i);
  }
  return all ? kExitOk : kExitInternal;
}

// FILE is a stroke file and `values` what `recognize --json` printed.
int verify_recognitions(const std::string& path, const std::string& answer_path,
                        const std::vector<JsonValue>& values, bool as_json) {
  std::vector<RecognitionAnswer> answers;
  std::vector<std::vector<std::vector<PointD>>> strokes;
  try {
    std::vector<FileStroke> file;
    try {
      file = read_stroke_file(path);
    } catch (const StrokeFileError& e) {
      throw InputError(e.what());
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (is_recognition_summary(values[i])) continue;
      try {
        answers.push_back(recognition_from_json(values[i]));
        strokes.push_back(strokes_of(file, answers.back()));
      } catch (const InputError& e) {
        throw InputError(answer_path + ": answer " + std::to_string(i + 1) + ": " + e.what());
      }
    }
    if (answers.empty()) throw InputError(answer_path + ": no answer");
  } catch (const InputError& e) {
    std::fprintf(stderr, "penshape verify: %s\n", e.what());
    return kExitBadInput;
  }
  return check_each(
      answer_path, answers.size(),
      [&](std::size_t i) { return verify_recognition(strokes[i], answers[i].claim); },
      [&](const VerifyReport& rep, std::size_t i) {
        print_recognition(rep, answers[i], i, answers.size(), as_json);
      });
}

} // namespace

int run_verify(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--help"}, .options = {}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 2) throw UsageError("expected FILE and ANSWER.json");
  const std::string& path = parsed.positionals()[0];
  const std::string& answer_path = parsed.positionals()[1];
  std::vector<DeconstructionClaim> claims;
  PolygonSet q;
  {
    // Recognition answers (they name a class) go with a stroke file.
    std::vector<JsonValue> values;
    try {
      values = parse_json_values(read_text(answer_path));
    } catch (const JsonError& e) {
      std::fprintf(stderr, "penshape verify: %s: %s\n", answer_path.c_str(), e.what());
      return kExitBadInput;
    } catch (const InputError& e) {
      std::fprintf(stderr, "penshape verify: %s\n", e.what());
      return kExitBadInput;
    }
    if (!values.empty() && is_recognition_answer(values.front())) {
      return verify_recognitions(path, answer_path, values, parsed.flag("--json"));
    }
  }
  try {
    q = read_polygon_file(path);
    if (q.empty()) throw InputError(path + ": no polygon");
    if (auto problem = region_problem(q)) {
      throw InputError(path + ": not a valid region: " + *problem);
    }
    std::vector<JsonValue> values;
    try {
      values = parse_json_values(read_text(answer_path));
    } catch (const JsonError& e) {
      throw InputError(answer_path + ": " + e.what());
    }
    if (values.empty()) throw InputError(answer_path + ": no answer");
    for (std::size_t i = 0; i < values.size(); ++i) {
      try {
        claims.push_back(claim_from_json(values[i]));
      } catch (const InputError& e) {
        throw InputError(answer_path + ": answer " + std::to_string(i + 1) + ": " + e.what());
      }
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "penshape verify: %s\n", e.what());
    return kExitBadInput;
  }
  return check_each(
      answer_path, claims.size(),
      [&](std::size_t i) { return verify_deconstruction(q, claims[i]); },
      [&](const VerifyReport& rep, std::size_t i) {
        print(rep, claims[i], i, claims.size(), parsed.flag("--json"));
      });
}

} // namespace penshape::cli
