// The writing/drawing decision of `penshape recognize` (recognize_intent.hpp).
#include "recognize_intent.hpp"

namespace penshape::cli {

std::vector<IntentDecision> intents_of(const std::vector<FileStroke>& batch) {
  std::vector<IntentStroke> page;
  page.reserve(batch.size());
  for (const FileStroke& s : batch) page.emplace_back(s.points);
  return decide_intent(page);
}

IntentDecision intent_of_answer(const std::vector<IntentDecision>& intents,
                                const std::vector<std::size_t>& strokes) {
  IntentDecision answer{Intent::kWriting, 0.0};
  for (const std::size_t i : strokes) {
    if (intents[i].intent == Intent::kDrawing) answer.intent = Intent::kDrawing;
    answer.writing_score += intents[i].writing_score;
  }
  if (!strokes.empty()) answer.writing_score /= static_cast<double>(strokes.size());
  return answer;
}

} // namespace penshape::cli
