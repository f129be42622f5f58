#include "compiler.h"

#include "builtins.h"
#include "parser.h"
#include "suggest.h"
#include "tape_builder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

namespace fl::formula {

const char* definitionKindName(DefinitionKind kind) {
    switch (kind) {
    case DefinitionKind::Generic:
        return "generic";
    case DefinitionKind::Implicit:
        return "implicit";
    case DefinitionKind::Parametric:
        return "parametric";
    case DefinitionKind::Colour:
        return "colour";
    case DefinitionKind::Force:
        return "force";
    }
    return "generic";
}

namespace {

// Unwinds the compiler after an error that makes going on pointless (a
// limit, or an error inside an unrolled loop). Never escapes compile().
struct Abort {};

struct Variable {
    Val value;
    bool maybeUndefined = false; // assigned on some paths only
    SourceRange assignedAt;
};

// Straight-line control state: `done` is 1 where a return has happened
// (possibly under a condition), `result` the value returned there.
struct Frame {
    std::map<std::string, Variable> vars;
    Val done = Val::constant(0.0);
    Val result;
    bool hasResult = false;
    std::string functionName; // empty at top level
};

class Compiler {
  public:
    Compiler(const Program& program, const CompileOptions& options, std::vector<Diagnostic>& diags)
        : program_(program), options_(options), diags_(diags) {}

    long expansionSteps() const { return expansionSteps_; }

    std::optional<Tape> run() {
        try {
            declareInputs();
            declareParameters();
            declareFunctions();
            if (hasErrors(diags_)) return std::nullopt;
            Frame top;
            std::vector<TapeBuilder::Output> outputs;
            executeTop(top, outputs);
            for (const auto& [name, fn] : functions_) {
                if (calledFunctions_.count(name)) continue;
                Frame scratch;
                scratch.functionName = name;
                for (const std::string& p : fn->params)
                    scratch.vars[p] = Variable{};
                checkNames(fn->body, scratch);
                warning(fn->nameRange, "function '" + name + "' is never called",
                        "call it, or remove it");
            }
            if (hasErrors(diags_)) return std::nullopt;
            Tape tape = tb_.finish(outputs, params_);
            warnAlwaysUndefined(tape);
            if (tape.code.size() > options_.limits.maxTapeSize) tooLarge(tape.code.size());
            return tape;
        } catch (const Abort&) {
            return std::nullopt;
        }
    }

  private:
    const Program& program_;
    const CompileOptions& options_;
    std::vector<Diagnostic>& diags_;
    TapeBuilder tb_;
    std::vector<ParameterInfo> params_;
    std::map<std::string, Val> paramVals_;
    std::map<std::string, const FunctionDecl*> functions_;
    std::vector<std::string> callStack_;
    bool inputAvailable_[kInputCount] = {};
    long unrolled_ = 0;
    long expansionSteps_ = 0;
    int errorCount_ = 0;
    std::set<std::string> calledFunctions_;
    std::set<const void*> checkedDeadBlocks_;
    std::set<std::string> allAssigned_;
    bool allAssignedCollected_ = false;
    const SourceRange* colourReturn_ = nullptr; // a top-level return in a colour definition
    const SourceRange* colourOutput_ = nullptr; // a top-level assignment to r, g or b

    // ---- diagnostics ---------------------------------------------------

    void error(const SourceRange& r, std::string msg, std::string hint = {}) {
        diags_.push_back({Severity::Error, r, std::move(msg), std::move(hint)});
        if (++errorCount_ >= options_.limits.maxErrors) {
            diags_.push_back({Severity::Error, r, "too many errors; stopping here",
                              "fix the errors above first"});
            throw Abort{};
        }
    }
    void warning(const SourceRange& r, std::string msg, std::string hint = {}) {
        diags_.push_back({Severity::Warning, r, std::move(msg), std::move(hint)});
    }
    [[noreturn]] void tooLarge(std::size_t n) {
        error(tb_.origin(),
              "formula is too large: " + std::to_string(n) +
                  " operations after unrolling (the limit is " +
                  std::to_string(options_.limits.maxTapeSize) + ")",
              "reduce loop counts or split the definition");
        throw Abort{};
    }
    // Inlining can multiply work without growing the tape (shared subexpressions
    // hash-cons away), so the work itself is bounded too.
    void countStep(const SourceRange& where) {
        if (++expansionSteps_ <= options_.limits.maxExpansionSteps) return;
        error(where,
              "formula expands to too much work: more than " +
                  std::to_string(options_.limits.maxExpansionSteps) +
                  " steps after inlining functions and unrolling loops",
              "call functions fewer times, or use fewer loop iterations");
        throw Abort{};
    }

    void checkSize() {
        // nodes include dead ones; a generous multiple keeps the check cheap and the memory bounded
        if (tb_.nodeCount() > options_.limits.maxTapeSize * 2) tooLarge(tb_.nodeCount());
    }

    // ---- names ---------------------------------------------------------

    static int inputIndex(std::string_view name) {
        for (int i = 0; i < kInputCount; ++i)
            if (name == kInputNames[i]) return i;
        return -1;
    }
    DefinitionKind kind() const { return options_.kind; }

    std::vector<std::string> outputNames() const {
        switch (kind()) {
        case DefinitionKind::Parametric:
            return {"x", "y", "z"};
        case DefinitionKind::Colour:
            return {"r", "g", "b"};
        case DefinitionKind::Force:
            return {"fx", "fy", "fz"};
        default:
            return {};
        }
    }
    bool isOutputName(std::string_view name) const {
        for (const std::string& o : outputNames())
            if (o == name) return true;
        return false;
    }

    void declareInputs() {
        auto allow = [&](std::initializer_list<Input> inputs) {
            for (Input i : inputs)
                inputAvailable_[static_cast<int>(i)] = true;
        };
        switch (kind()) {
        case DefinitionKind::Implicit:
            allow({Input::X, Input::Y, Input::Z, Input::T});
            break;
        case DefinitionKind::Parametric:
            allow({Input::U, Input::V, Input::W, Input::T});
            break;
        case DefinitionKind::Colour:
        case DefinitionKind::Force: // u, v, w: the point in the force's unit domain
        case DefinitionKind::Generic:
            allow({Input::X, Input::Y, Input::Z, Input::T, Input::U, Input::V, Input::W});
            break;
        }
    }

    bool reservedName(const std::string& name, const SourceRange& r, const char* what) {
        if (inputIndex(name) >= 0 && inputAvailable_[inputIndex(name)]) {
            error(r, "'" + name + "' is an input coordinate and cannot be used as a " + what,
                  "choose another name");
            return true;
        }
        if (name == "pi" || name == "e") {
            error(r, "'" + name + "' is a built-in constant and cannot be used as a " + what,
                  "choose another name");
            return true;
        }
        if (findBuiltin(name)) {
            error(r, "'" + name + "' is a built-in function and cannot be used as a " + what,
                  "choose another name");
            return true;
        }
        return false;
    }

    Val constantExpression(const Expr& e, const char* what) {
        Frame scratch;
        Val v =
            tb_.resolveConstant(expr(e, scratch)); // (an always-NaN part is reported at the end)
        if (!v.isConst()) {
            error(e.range, std::string(what) + " must be a constant number",
                  "use numbers and pi or e only");
            return Val::constant(0.0);
        }
        return v;
    }

    void declareParameters() {
        auto add = [&](const std::string& name, double def, bool hasRange, double lo, double hi) {
            ParameterInfo p;
            p.name = name;
            p.reg = kInputCount + static_cast<std::int32_t>(params_.size());
            p.defaultValue = def;
            p.hasRange = hasRange;
            p.lo = lo;
            p.hi = hi;
            paramVals_[name] = tb_.parameter(static_cast<std::int32_t>(params_.size()));
            params_.push_back(p);
        };
        for (const ExternalParameter& p : options_.parameters)
            add(p.name, p.defaultValue, p.hasRange, p.lo, p.hi);
        for (const ParamDecl& d : program_.params) {
            if (reservedName(d.name, d.nameRange, "parameter name")) continue;
            if (paramVals_.count(d.name)) {
                error(d.nameRange, "parameter '" + d.name + "' is declared twice",
                      "remove one declaration");
                continue;
            }
            double def = d.defaultValue
                             ? constantExpression(*d.defaultValue, "a parameter's default").c
                             : 0.0;
            double lo = 0, hi = 0;
            bool hasRange = d.lo && d.hi;
            if (hasRange) {
                lo = constantExpression(*d.lo, "a parameter's range").c;
                hi = constantExpression(*d.hi, "a parameter's range").c;
                if (!(lo <= hi)) {
                    error(d.range,
                          "the range of '" + d.name + "' is empty (low end above high end)",
                          "write the range as [low, high]");
                } else if (!(def >= lo && def <= hi)) {
                    warning(d.range, "the default of '" + d.name + "' lies outside its range",
                            "move the default into [low, high]");
                }
            }
            add(d.name, def, hasRange, lo, hi);
        }
    }

    void declareFunctions() {
        for (const FunctionDecl& f : program_.functions) {
            if (reservedName(f.name, f.nameRange, "function name")) continue;
            if (functions_.count(f.name)) {
                error(f.nameRange, "function '" + f.name + "' is defined twice",
                      "rename one of them");
                continue;
            }
            for (std::size_t i = 0; i < f.params.size(); ++i) {
                for (std::size_t j = 0; j < i; ++j)
                    if (f.params[i] == f.params[j])
                        error(f.paramRanges[i], "parameter '" + f.params[i] + "' appears twice",
                              "rename one of them");
            }
            functions_[f.name] = &f;
        }
    }

    std::vector<std::string> knownNames(const Frame& frame) const {
        std::vector<std::string> names;
        for (const auto& [n, v] : frame.vars)
            names.push_back(n);
        for (int i = 0; i < kInputCount; ++i)
            if (inputAvailable_[i]) names.push_back(kInputNames[i]);
        for (const ParameterInfo& p : params_)
            names.push_back(p.name);
        names.push_back("pi");
        names.push_back("e");
        return names;
    }

    std::vector<std::string> knownFunctions() const {
        std::vector<std::string> names;
        for (const BuiltinInfo& b : builtinTable())
            names.emplace_back(b.name);
        for (const auto& [n, f] : functions_)
            names.push_back(n);
        return names;
    }

    // ---- statements ----------------------------------------------------

    void executeTop(Frame& top, std::vector<TapeBuilder::Output>& outputs) {
        const auto& stmts = program_.statements;
        const bool multiOutput = !outputNames().empty();
        Val lastValue;
        bool hasLastValue = false;
        SourceRange lastRange;
        for (std::size_t i = 0; i < stmts.size(); ++i) {
            const Stmt& s = *stmts[i];
            if (s.kind == StmtKind::ExprStmt && i + 1 == stmts.size()) {
                // a final bare expression is the definition's value
                if (isDone(top)) {
                    warning(s.range,
                            "this expression is never reached: every path returned before it",
                            "remove it");
                    break;
                }
                tb_.setOrigin(s.range);
                lastValue = expr(*s.value, top);
                hasLastValue = true;
                lastRange = s.range;
                break;
            }
            exec(s, top);
        }
        if (hasLastValue) {
            if (top.hasResult) lastValue = tb_.select(top.done, top.result, lastValue);
            top.result = lastValue;
            top.hasResult = true;
            top.done = Val::constant(1.0);
        }

        if (colourReturn_ && colourOutput_) {
            error(*colourReturn_,
                  "a colour definition either assigns r, g and b or returns one value for the "
                  "colour map, not both",
                  "remove the 'return', or the assignments to r, g, b (see line " +
                      std::to_string(colourOutput_->begin.line) + ")");
            return;
        }
        if (multiOutput) {
            bool allAssigned = true;
            std::string missing;
            for (const std::string& o : outputNames()) {
                auto it = top.vars.find(o);
                if (it == top.vars.end()) {
                    allAssigned = false;
                    missing += missing.empty() ? o : ", " + o;
                }
            }
            if (allAssigned) {
                for (const std::string& o : outputNames()) {
                    const Variable& v = top.vars.at(o);
                    if (v.maybeUndefined)
                        error(v.assignedAt, "output '" + o + "' is assigned only on some paths",
                              "assign it before the 'if' or in every branch");
                    outputs.push_back({o, v.value});
                }
                return;
            }
            if (kind() == DefinitionKind::Colour && top.hasResult) {
                finishSingle(top, outputs);
                return;
            }
            SourceRange where = stmts.empty() ? SourceRange{} : stmts.back()->range;
            std::string example = kind() == DefinitionKind::Parametric
                                      ? "x = cos(u); y = sin(u); z = v;"
                                  : kind() == DefinitionKind::Force ? "fx = 0; fy = -1; fz = 0;"
                                                                    : "r = 1; g = 0.5; b = 0;";
            error(where,
                  std::string("a ") + definitionKindName(kind()) + " definition must assign " +
                      outputNames()[0] + ", " + outputNames()[1] + " and " + outputNames()[2] +
                      (allAssigned ? "" : "; missing: " + missing),
                  "write, for example: " + example);
            return;
        }
        if (!top.hasResult) {
            SourceRange where = stmts.empty() ? SourceRange{} : stmts.back()->range;
            error(where, "the definition gives no value",
                  "end it with an expression or with 'return ...;'");
            return;
        }
        finishSingle(top, outputs);
    }

    void finishSingle(Frame& top, std::vector<TapeBuilder::Output>& outputs) {
        if (!top.done.isConst(1.0)) {
            error(program_.statements.empty() ? SourceRange{} : program_.statements.back()->range,
                  "not every path returns a value", "add a final 'return ...;'");
            return;
        }
        outputs.push_back({"value", top.result});
    }

    static bool isDone(const Frame& f) { return f.done.isConst(1.0); }

    void execBlock(const std::vector<StmtPtr>& body, Frame& f) {
        for (const StmtPtr& s : body) {
            if (isDone(f)) {
                warning(s->range, "this code is never reached: every path returned before it",
                        "remove it");
                return;
            }
            exec(*s, f);
        }
    }

    void exec(const Stmt& s, Frame& f) {
        countStep(s.range);
        tb_.setOrigin(s.range);
        checkSize();
        switch (s.kind) {
        case StmtKind::Assign:
            assign(s, f);
            break;
        case StmtKind::Block:
            execBlock(s.body, f);
            break;
        case StmtKind::ExprStmt:
            expr(*s.value, f);
            warning(s.range, "the value of this expression is not used",
                    "assign it to a name, or 'return' it");
            break;
        case StmtKind::Return:
            doReturn(s, f);
            break;
        case StmtKind::If:
            doIf(s, f);
            break;
        case StmtKind::For:
            doFor(s, f);
            break;
        }
    }

    void assign(const Stmt& s, Frame& f) {
        const std::string& name = s.name;
        int in = inputIndex(name);
        bool isOutputCoordinate = isOutputName(name);
        if (in >= 0 && inputAvailable_[in] && !isOutputCoordinate) {
            error(s.nameRange, "'" + name + "' is an input coordinate here and cannot be assigned",
                  kind() == DefinitionKind::Implicit || kind() == DefinitionKind::Generic
                      ? "use a new name such as " + name +
                            "1; to write parametric x, y, z use a parametric definition"
                      : "use a new name such as " + name + "1");
            return;
        }
        if (paramVals_.count(name)) {
            error(s.nameRange,
                  "'" + name + "' is a parameter and cannot be changed inside the formula",
                  "use a local variable with another name");
            return;
        }
        if (reservedName(name, s.nameRange, "variable")) return;
        if (isOutputCoordinate && kind() == DefinitionKind::Colour && f.functionName.empty())
            colourOutput_ = &s.nameRange;
        Val value = expr(*s.value, f);
        auto it = f.vars.find(name);
        const Val* old = nullptr;
        if (it != f.vars.end()) old = &it->second.value;
        if (s.assignOp != AssignOp::Set) {
            if (!old || it->second.maybeUndefined) {
                error(s.nameRange, "'" + name + "' is used before it has a value",
                      "assign it first, for example: " + name + " = 0;");
                return;
            }
            tb_.setOrigin(s.range);
            switch (s.assignOp) {
            case AssignOp::Add:
                value = tb_.add(*old, value);
                break;
            case AssignOp::Sub:
                value = tb_.sub(*old, value);
                break;
            case AssignOp::Mul:
                value = tb_.mul(*old, value);
                break;
            case AssignOp::Div:
                value = tb_.div(*old, value);
                break;
            case AssignOp::Set:
                break;
            }
        }
        // No guard is needed after a conditional return: the paths that
        // returned have their result fixed (later returns are merged with
        // select(done, result, …)), so what they assign is never read.
        Variable v;
        v.value = value;
        v.assignedAt = s.nameRange;
        f.vars[name] = v;
    }

    void doReturn(const Stmt& s, Frame& f) {
        if (kind() != DefinitionKind::Generic && kind() != DefinitionKind::Implicit &&
            kind() != DefinitionKind::Colour && f.functionName.empty()) {
            error(s.range,
                  std::string("'return' has no meaning in a ") + definitionKindName(kind()) +
                      " definition",
                  "assign the outputs " + outputNames()[0] + ", " + outputNames()[1] + ", " +
                      outputNames()[2] + " instead");
            return;
        }
        if (kind() == DefinitionKind::Colour && f.functionName.empty()) colourReturn_ = &s.range;
        Val v = expr(*s.value, f);
        tb_.setOrigin(s.range);
        if (f.hasResult) v = tb_.select(f.done, f.result, v);
        f.result = v;
        f.hasResult = true;
        f.done = Val::constant(1.0);
    }

    void doIf(const Stmt& s, Frame& f) {
        Val cond = tb_.resolveConstant(expr(*s.value, f));
        if (cond.isConst()) {
            bool taken = cond.c < 0.0 || cond.c > 0.0;
            if (taken)
                execBlock(s.body, f);
            else if (s.hasElse)
                execBlock(s.elseBody, f);
            // the branch never taken is not compiled, but its names are still checked
            checkNames(taken ? s.elseBody : s.body, f);
            return;
        }
        Frame before = f;
        execBlock(s.body, f);
        Frame thenFrame = std::move(f);
        f = before;
        if (s.hasElse) execBlock(s.elseBody, f);
        Frame elseFrame = std::move(f);
        f = std::move(before);
        tb_.setOrigin(s.range);
        // A branch that surely returned contributes no variables: code after
        // the `if` runs only where the other branch was taken.
        if (isDone(thenFrame) != isDone(elseFrame)) {
            const Frame& continuing = isDone(thenFrame) ? elseFrame : thenFrame;
            f.vars = continuing.vars;
        } else {
            f.vars = mergeVariables(cond, thenFrame, elseFrame);
        }
        f.done = tb_.select(cond, thenFrame.done, elseFrame.done);
        if (thenFrame.hasResult && elseFrame.hasResult)
            f.result = tb_.select(cond, thenFrame.result, elseFrame.result);
        else if (thenFrame.hasResult)
            f.result = thenFrame.result;
        else if (elseFrame.hasResult)
            f.result = elseFrame.result;
        f.hasResult = thenFrame.hasResult || elseFrame.hasResult;
    }

    std::map<std::string, Variable> mergeVariables(Val cond, const Frame& thenFrame,
                                                   const Frame& elseFrame) {
        std::map<std::string, Variable> merged;
        for (const auto& [name, tv] : thenFrame.vars) {
            auto e = elseFrame.vars.find(name);
            Variable v = tv;
            if (e == elseFrame.vars.end()) {
                v.maybeUndefined = true;
            } else {
                v.value = tb_.select(cond, tv.value, e->second.value);
                v.maybeUndefined = tv.maybeUndefined || e->second.maybeUndefined;
            }
            merged[name] = v;
        }
        for (const auto& [name, ev] : elseFrame.vars) {
            if (merged.count(name)) continue;
            Variable v = ev;
            v.maybeUndefined = true;
            merged[name] = v;
        }
        return merged;
    }

    void doFor(const Stmt& s, Frame& f) {
        const std::string& var = s.name;
        if (reservedName(var, s.nameRange, "loop variable")) return;
        if (paramVals_.count(var)) {
            error(s.nameRange, "'" + var + "' is a parameter and cannot be a loop variable",
                  "use another name, such as i");
            return;
        }
        if (s.step->name != var) {
            error(s.step->nameRange,
                  "the loop step changes '" + s.step->name + "', not the loop variable '" + var +
                      "'",
                  "write: " + var + "++");
            return;
        }
        Val init = tb_.resolveConstant(expr(*s.value, f));
        if (!init.isConst()) {
            error(s.value->range, "a loop's first value must be known when the formula is compiled",
                  "use a number here");
            return;
        }
        Variable loopVar;
        loopVar.value = init;
        loopVar.assignedAt = s.nameRange;
        f.vars[var] = loopVar;
        for (;;) {
            Val c = tb_.resolveConstant(expr(*s.condition, f));
            if (!c.isConst()) {
                error(s.condition->range,
                      "a loop's condition must be known when the formula is compiled",
                      "compare the loop variable with a number, e.g. i < 8");
                throw Abort{};
            }
            if (!(c.c < 0.0 || c.c > 0.0)) break;
            if (++unrolled_ > options_.limits.maxUnrolledIterations) {
                error(s.range,
                      "loops unroll to more than " +
                          std::to_string(options_.limits.maxUnrolledIterations) +
                          " iterations in total",
                      "use fewer iterations or a closed-form expression");
                throw Abort{};
            }
            execBlock(s.body, f);
            if (isDone(f)) break;
            checkSize();
            assign(*s.step, f);
            if (hasErrors(diags_)) throw Abort{};
            f.vars[var].value = tb_.resolveConstant(f.vars[var].value);
            if (!f.vars[var].value.isConst()) {
                error(s.step->range,
                      "the loop step must change the loop variable by a known amount",
                      "write: i++ or i += 1");
                throw Abort{};
            }
        }
    }

    // Operations with only constant operands survive folding only when they
    // are NaN for every point (TapeBuilder keeps them); the live ones are
    // reported once per place in the source.
    void warnAlwaysUndefined(const Tape& tape) {
        std::set<std::size_t> reported;
        for (const SourceRange& where : tb_.resolvedUndefined()) {
            if (!reported.insert(where.begin.offset).second) continue;
            warning(where, "this is undefined (NaN) for every point", "check the arguments");
        }
        for (const Instruction& ins : tape.code) {
            const int arity = opArity(ins.op);
            bool allConst =
                ins.a.isConst() && (arity < 2 || ins.b.isConst()) && (arity < 3 || ins.c.isConst());
            if (!allConst || ins.origin < 0) continue;
            const SourceRange& where = tape.origins[static_cast<std::size_t>(ins.origin)];
            if (!reported.insert(where.begin.offset).second) continue;
            warning(where,
                    std::string("'") + opSourceName(ins.op) +
                        "' is undefined (NaN) here for every point",
                    "check the arguments: e.g. log and sqrt need non-negative values");
        }
    }

    // ---- names in code that is never compiled --------------------------
    // Dead branches and uncalled functions produce no tape, but a typo in
    // them is still a typo: check names and call arity without evaluating.

    void collectAssigned(const std::vector<StmtPtr>& body, std::set<std::string>& names) const {
        for (const StmtPtr& s : body) {
            if (s->kind == StmtKind::Assign || s->kind == StmtKind::For) names.insert(s->name);
            collectAssigned(s->body, names);
            collectAssigned(s->elseBody, names);
        }
    }

    // Flow-insensitive on purpose: a name assigned anywhere in the program
    // counts as known (a dead branch in an unrolled loop may read a variable
    // assigned later in the body). Each dead block is checked once.
    void checkNames(const std::vector<StmtPtr>& body, const Frame& frame) {
        if (!checkedDeadBlocks_.insert(&body).second) return;
        if (!allAssignedCollected_) {
            collectAssigned(program_.statements, allAssigned_);
            for (const FunctionDecl& fn : program_.functions)
                collectAssigned(fn.body, allAssigned_);
            allAssignedCollected_ = true;
        }
        std::set<std::string> known = allAssigned_;
        for (const auto& [name, v] : frame.vars)
            known.insert(name);
        checkNamesIn(body, known);
    }

    void checkNamesIn(const std::vector<StmtPtr>& body, const std::set<std::string>& known) {
        for (const StmtPtr& s : body) {
            for (const Expr* e : {s->value.get(), s->condition.get()})
                if (e) checkNamesIn(*e, known);
            if (s->step && s->step->value) checkNamesIn(*s->step->value, known);
            checkNamesIn(s->body, known);
            checkNamesIn(s->elseBody, known);
        }
    }

    void checkNamesIn(const Expr& e, const std::set<std::string>& known) {
        for (const ExprPtr& a : e.args)
            checkNamesIn(*a, known);
        if (e.kind == ExprKind::Name) {
            int in = inputIndex(e.name);
            bool ok = known.count(e.name) || paramVals_.count(e.name) || e.name == "pi" ||
                      e.name == "e" || (in >= 0 && inputAvailable_[in]);
            if (!ok) {
                std::vector<std::string> names(known.begin(), known.end());
                for (const std::string& n : knownNames(Frame{}))
                    names.push_back(n);
                std::string near = closestName(e.name, names);
                error(e.range, "unknown name '" + e.name + "'",
                      near.empty() ? "define it first" : "did you mean '" + near + "'?");
            }
        } else if (e.kind == ExprKind::Call) {
            if (auto fit = functions_.find(e.name); fit != functions_.end())
                checkArity(*fit->second, e);
            else if (const BuiltinInfo* info = findBuiltin(e.name))
                checkArity(*info, e);
            else
                unknownFunction(e);
        }
    }

    // ---- calls: checks shared by compiled and never-compiled code --------

    // Reports a wrong number of arguments; true when the count is right.
    bool checkArity(const FunctionDecl& fn, const Expr& e) {
        if (e.args.size() == fn.params.size()) return true;
        error(e.range,
              "'" + fn.name + "' takes " + plural(fn.params.size(), "argument") +
                  " but was given " + std::to_string(e.args.size()),
              "see its definition at line " + std::to_string(fn.nameRange.begin.line));
        return false;
    }

    bool checkArity(const BuiltinInfo& info, const Expr& e) {
        const int argc = static_cast<int>(e.args.size());
        if (argc >= info.minArgs && (info.maxArgs < 0 || argc <= info.maxArgs)) return true;
        std::string expected = info.minArgs == info.maxArgs ? plural(info.minArgs, "argument")
                               : info.maxArgs < 0 ? "at least " + plural(info.minArgs, "argument")
                                                  : std::to_string(info.minArgs) + " to " +
                                                        plural(info.maxArgs, "argument");
        error(e.range,
              "'" + e.name + "' takes " + expected + " but was given " + std::to_string(argc),
              "use " + std::string(info.signature));
        return false;
    }

    void unknownFunction(const Expr& e) {
        std::string near = closestName(e.name, knownFunctions());
        error(e.nameRange, "unknown function '" + e.name + "'",
              near.empty() ? "see the formula reference for the built-in functions"
                           : "did you mean '" + near + "'?");
    }

    // ---- expressions ---------------------------------------------------

    Val readName(const Expr& e, Frame& f) {
        const std::string& name = e.name;
        if (auto it = f.vars.find(name); it != f.vars.end()) {
            if (it->second.maybeUndefined) {
                error(e.range,
                      "'" + name + "' may have no value here: it is assigned only on some paths",
                      "assign it before the 'if', or in every branch");
                return Val::constant(0.0);
            }
            return it->second.value;
        }
        int in = inputIndex(name);
        if (in >= 0) {
            if (inputAvailable_[in]) return tb_.input(static_cast<Input>(in));
            if (isOutputName(name)) {
                error(e.range,
                      "'" + name + "' is an output of this " + definitionKindName(kind()) +
                          " definition and has no value yet",
                      "assign " + name + " before reading it");
            } else {
                error(e.range,
                      "'" + name + "' is not available in a " + definitionKindName(kind()) +
                          " definition",
                      kind() == DefinitionKind::Parametric
                          ? "parametric definitions use u, v, w and t"
                          : "use x, y, z and t");
            }
            return Val::constant(0.0);
        }
        if (auto it = paramVals_.find(name); it != paramVals_.end()) return it->second;
        if (name == "pi") return Val::constant(std::numbers::pi);
        if (name == "e") return Val::constant(std::numbers::e);
        if (findBuiltin(name) || functions_.count(name)) {
            error(e.range, "'" + name + "' is a function; call it with arguments",
                  "write " + name + "(...)");
            return Val::constant(0.0);
        }
        std::string near = closestName(name, knownNames(f));
        error(e.range, "unknown name '" + name + "'",
              near.empty() ? "define it first, or declare it: param " + name + " = 1;"
                           : "did you mean '" + near + "'?");
        return Val::constant(0.0);
    }

    Val setOp(BinaryOp op, Val a, Val b) {
        const SetOperationMode& mode = options_.setOperations;
        if (op == BinaryOp::Difference) b = tb_.neg(b);
        bool intersect = op != BinaryOp::Union;
        if (mode.kind == SetOperationMode::Kind::MinMax)
            return intersect ? tb_.min(a, b) : tb_.max(a, b);
        return tb_.emit(intersect ? Op::RIntersect : Op::RUnion, a, b, {}, mode.m, mode.alpha);
    }

    Val expr(const Expr& e, Frame& f) {
        countStep(e.range);
        switch (e.kind) {
        case ExprKind::Number:
            return Val::constant(e.number);
        case ExprKind::Name:
            return readName(e, f);
        case ExprKind::Unary: {
            Val a = expr(*e.args[0], f);
            tb_.setOrigin(e.range);
            switch (e.unaryOp) {
            case UnaryOp::Plus:
                return a;
            case UnaryOp::Negate:
            case UnaryOp::Complement:
                return tb_.neg(a);
            case UnaryOp::Not:
                return tb_.emit(Op::Not, a);
            }
            return a;
        }
        case ExprKind::Binary: {
            Val a = expr(*e.args[0], f);
            Val b = expr(*e.args[1], f);
            tb_.setOrigin(e.range);
            switch (e.binaryOp) {
            case BinaryOp::Add:
                return tb_.add(a, b);
            case BinaryOp::Sub:
                return tb_.sub(a, b);
            case BinaryOp::Mul:
                return tb_.mul(a, b);
            case BinaryOp::Div:
                return tb_.div(a, b);
            case BinaryOp::Pow:
                return tb_.power(a, b);
            case BinaryOp::Less:
                return tb_.emit(Op::Less, a, b);
            case BinaryOp::LessEqual:
                return tb_.emit(Op::LessEq, a, b);
            case BinaryOp::Greater:
                return tb_.emit(Op::Greater, a, b);
            case BinaryOp::GreaterEqual:
                return tb_.emit(Op::GreaterEq, a, b);
            case BinaryOp::Equal:
                return tb_.emit(Op::Equal, a, b);
            case BinaryOp::NotEqual:
                return tb_.emit(Op::NotEqual, a, b);
            case BinaryOp::And:
                return tb_.emit(Op::And, a, b);
            case BinaryOp::Or:
                return tb_.emit(Op::Or, a, b);
            case BinaryOp::Intersect:
            case BinaryOp::Union:
            case BinaryOp::Difference:
                return setOp(e.binaryOp, a, b);
            }
            return a;
        }
        case ExprKind::Ternary: {
            Val c = expr(*e.args[0], f);
            Val a = expr(*e.args[1], f);
            Val b = expr(*e.args[2], f);
            tb_.setOrigin(e.range);
            return tb_.select(c, a, b);
        }
        case ExprKind::Call:
            return call(e, f);
        }
        return Val::constant(0.0);
    }

    static std::string plural(std::size_t n, const char* word) {
        return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
    }

    Val call(const Expr& e, Frame& f) {
        const std::string& name = e.name;
        std::vector<Val> args;
        args.reserve(e.args.size());
        for (const ExprPtr& a : e.args)
            args.push_back(expr(*a, f));
        tb_.setOrigin(e.range);

        if (auto fit = functions_.find(name); fit != functions_.end())
            return callUser(*fit->second, e, args);

        const BuiltinInfo* info = findBuiltin(name);
        if (!info) {
            if (f.vars.count(name) || paramVals_.count(name) || inputIndex(name) >= 0) {
                error(e.nameRange, "'" + name + "' is a value, not a function",
                      "multiplication needs '*': write " + name + "*(...)");
                return Val::constant(0.0);
            }
            unknownFunction(e);
            return Val::constant(0.0);
        }
        if (!checkArity(*info, e)) return Val::constant(0.0);
        const int argc = static_cast<int>(args.size());
        BuiltinContext ctx{tb_, {}, {}, {}};
        if (info->readsCoordinates) {
            if (!inputAvailable_[0]) {
                error(e.nameRange,
                      "'" + name + "' reads x, y, z, which a " + definitionKindName(kind()) +
                          " definition does not have",
                      "use primitives in implicit definitions");
                return Val::constant(0.0);
            }
            ctx.x = tb_.input(Input::X);
            ctx.y = tb_.input(Input::Y);
            ctx.z = tb_.input(Input::Z);
        }
        Val result;
        BuiltinError err;
        if (!lowerBuiltin(*info, ctx, args, result, err)) {
            const SourceRange& where =
                err.argument >= 0 && err.argument < argc ? e.args[err.argument]->range : e.range;
            error(where, err.message, err.suggestion);
            return Val::constant(0.0);
        }
        return result;
    }

    Val callUser(const FunctionDecl& fn, const Expr& e, const std::vector<Val>& args) {
        if (!checkArity(fn, e)) return Val::constant(0.0);
        if (std::find(callStack_.begin(), callStack_.end(), fn.name) != callStack_.end()) {
            error(e.nameRange, "'" + fn.name + "' calls itself; recursion is not supported",
                  "formulas must be finite: use a for loop instead");
            throw Abort{};
        }
        if (static_cast<int>(callStack_.size()) >= options_.limits.maxCallDepth) {
            error(e.nameRange, "functions call each other too deeply", "flatten the calls");
            throw Abort{};
        }
        callStack_.push_back(fn.name);
        calledFunctions_.insert(fn.name);
        Frame frame;
        frame.functionName = fn.name;
        for (std::size_t i = 0; i < args.size(); ++i) {
            Variable v;
            v.value = args[i];
            v.assignedAt = fn.paramRanges[i];
            frame.vars[fn.params[i]] = v;
        }
        execBlock(fn.body, frame);
        callStack_.pop_back();
        if (!frame.hasResult || !frame.done.isConst(1.0)) {
            error(fn.nameRange, "function '" + fn.name + "' does not return a value on every path",
                  "end it with 'return ...;'");
            throw Abort{};
        }
        return frame.result;
    }
};

} // namespace

CompileResult compile(std::string_view source, const CompileOptions& options) {
    CompileResult result;
    Program program = parse(source, result.diagnostics, options.limits);
    if (hasErrors(result.diagnostics)) return result;
    Compiler compiler(program, options, result.diagnostics);
    std::optional<Tape> tape = compiler.run();
    result.expansionSteps = compiler.expansionSteps();
    if (!hasErrors(result.diagnostics)) result.tape = std::move(tape);
    return result;
}

} // namespace fl::formula
