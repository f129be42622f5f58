#pragma once
// One check per kind of requirement, over a submission as shown. Each says
// met or not with evidence and places, and spends its evaluations from the
// submission's one budget.
#include "requirement.h"
#include "solid_difference.h"
#include "submission_view.h"

namespace fl::grading {

RequirementResult checkShapeKind(const SubmissionView& view, const Requirement& r, Budget& budget);
RequirementResult checkSetOperations(const SubmissionView& view, const Requirement& r,
                                     Budget& budget, const CompareOptions& compare = {});
RequirementResult checkMorphing(const SubmissionView& view, const Requirement& r, Budget& budget);
RequirementResult checkAnimation(const SubmissionView& view, const Requirement& r);
RequirementResult checkLevelOfDetail(const SubmissionView& view, const Requirement& r);
// A shown FPdeSurface whose model was read and meshed.
RequirementResult checkPdeSurface(const SubmissionView& view, const Requirement& r);
RequirementResult checkFunctionColour(const SubmissionView& view, const Requirement& r,
                                      Budget& budget);
RequirementResult checkTangible(const SubmissionView& view, const Requirement& r, Budget& budget);

} // namespace fl::grading
