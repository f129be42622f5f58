#include "parser.h"

#include "lexer.h"

#include <algorithm>
#include <utility>

namespace fl::formula {
namespace {

// Thrown only inside the parser to unwind out of a statement after the
// first error in it; caught at statement level, so it never escapes parse().
struct SyntaxError {};

class Parser {
  public:
    Parser(std::vector<Token> tokens, std::vector<Diagnostic>& diags, const Limits& limits)
        : toks_(std::move(tokens)), diags_(diags), limits_(limits) {}

    Program run() {
        Program program;
        while (!at(TokenKind::End)) {
            std::size_t before = pos_;
            try {
                if (at(TokenKind::KwFunction)) {
                    program.functions.push_back(functionDecl());
                } else if (at(TokenKind::KwParam)) {
                    program.params.push_back(paramDecl());
                } else {
                    program.statements.push_back(statement(/*topLevel=*/true));
                }
            } catch (const SyntaxError&) {
                recover();
            }
            if (pos_ == before) ++pos_; // always make progress
            if (depthExceeded_) break;
        }
        program.isExpression = program.functions.empty() && program.params.empty() &&
                               program.statements.size() == 1 &&
                               program.statements[0]->kind == StmtKind::ExprStmt;
        return program;
    }

  private:
    std::vector<Token> toks_;
    std::vector<Diagnostic>& diags_;
    const Limits& limits_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    bool depthExceeded_ = false; // or too many errors: stop parsing
    int errors_ = 0;

    const Token& cur() const { return toks_[std::min(pos_, toks_.size() - 1)]; }
    const Token& peekTok(std::size_t ahead) const {
        return toks_[std::min(pos_ + ahead, toks_.size() - 1)];
    }
    bool at(TokenKind k) const { return cur().kind == k; }
    const Token& previous() const { return toks_[pos_ == 0 ? 0 : pos_ - 1]; }
    Token take() {
        Token t = cur();
        if (pos_ < toks_.size() - 1) ++pos_;
        return t;
    }
    bool accept(TokenKind k) {
        if (!at(k)) return false;
        take();
        return true;
    }

    [[noreturn]] void fail(const SourceRange& r, std::string msg, std::string hint = {}) {
        diags_.push_back({Severity::Error, r, std::move(msg), std::move(hint)});
        if (++errors_ >= limits_.maxErrors) {
            diags_.push_back({Severity::Error, r, "too many errors; stopping here",
                              "fix the errors above first"});
            depthExceeded_ = true; // stops the statement loop
        }
        throw SyntaxError{};
    }

    std::string found() const {
        const Token& t = cur();
        if (t.kind == TokenKind::End) return "the end of the formula";
        if (t.kind == TokenKind::Identifier || t.kind == TokenKind::Number)
            return "'" + t.text + "'";
        return tokenKindName(t.kind);
    }

    Token expect(TokenKind k, const std::string& what, std::string hint = {}) {
        if (at(k)) return take();
        if (cur().kind == TokenKind::Invalid) throw SyntaxError{}; // lexer already reported it
        // Point at the end of the previous token when something is missing,
        // which is where the student has to type.
        SourceRange where = cur().range;
        if (pos_ > 0 && (k == TokenKind::Semicolon || k == TokenKind::RParen ||
                         k == TokenKind::RBrace || k == TokenKind::RBracket)) {
            where = {previous().range.end, previous().range.end};
            where.end.column += 1;
            where.end.offset += 1;
        }
        if (hint.empty()) hint = std::string("add ") + tokenKindName(k);
        fail(where, std::string("expected ") + what + " but found " + found(), hint);
    }

    void recover() {
        // Skip to just after the next ';' or to a '}' / a keyword that starts a statement.
        while (!at(TokenKind::End)) {
            TokenKind k = cur().kind;
            if (k == TokenKind::Semicolon) {
                take();
                return;
            }
            if (k == TokenKind::RBrace || k == TokenKind::KwFunction || k == TokenKind::KwParam ||
                k == TokenKind::KwIf || k == TokenKind::KwFor || k == TokenKind::KwReturn)
                return;
            take();
        }
    }

    struct DepthGuard {
        Parser& p;
        explicit DepthGuard(Parser& parser, const SourceRange& r) : p(parser) {
            if (++p.depth_ > p.limits_.maxNestingDepth) {
                p.depthExceeded_ = true;
                --p.depth_;
                p.fail(r,
                       "formula is nested too deeply (more than " +
                           std::to_string(p.limits_.maxNestingDepth) + " levels)",
                       "split it into named parts with local variables or functions");
            }
        }
        ~DepthGuard() { --p.depth_; }
    };

    // ---- declarations -------------------------------------------------

    FunctionDecl functionDecl() {
        Token kw = take();
        FunctionDecl f;
        Token name = expect(TokenKind::Identifier, "a function name after 'function'");
        f.name = name.text;
        f.nameRange = name.range;
        expect(TokenKind::LParen, "'(' after the function name");
        if (!at(TokenKind::RParen)) {
            do {
                Token p = expect(TokenKind::Identifier, "a parameter name");
                f.params.push_back(p.text);
                f.paramRanges.push_back(p.range);
            } while (accept(TokenKind::Comma));
        }
        expect(TokenKind::RParen, "')' after the parameters");
        f.body = block();
        f.range = SourceRange::span(kw.range, previous().range);
        return f;
    }

    ParamDecl paramDecl() {
        Token kw = take();
        ParamDecl p;
        Token name = expect(TokenKind::Identifier, "a parameter name after 'param'");
        p.name = name.text;
        p.nameRange = name.range;
        expect(TokenKind::Assign, "'=' and a default value",
               "write: param " + p.name + " = 1 in [0, 2];");
        p.defaultValue = expression();
        if (accept(TokenKind::KwIn)) {
            expect(TokenKind::LBracket, "'[' to start the range", "write the range as [low, high]");
            p.lo = expression();
            expect(TokenKind::Comma, "',' between the range's ends",
                   "write the range as [low, high]");
            p.hi = expression();
            expect(TokenKind::RBracket, "']' to end the range");
        }
        expect(TokenKind::Semicolon, "';' after the parameter declaration");
        p.range = SourceRange::span(kw.range, previous().range);
        return p;
    }

    // ---- statements ---------------------------------------------------

    std::vector<StmtPtr> block() {
        expect(TokenKind::LBrace, "'{' to start a block");
        std::vector<StmtPtr> body;
        while (!at(TokenKind::RBrace) && !at(TokenKind::End)) {
            std::size_t before = pos_;
            try {
                body.push_back(statement(false));
            } catch (const SyntaxError&) {
                if (depthExceeded_) throw;
                recover();
            }
            if (pos_ == before) take();
        }
        expect(TokenKind::RBrace, "'}' to close the block");
        return body;
    }

    std::vector<StmtPtr> blockOrStatement() {
        if (at(TokenKind::LBrace)) return block();
        std::vector<StmtPtr> one;
        one.push_back(statement(false));
        return one;
    }

    bool atAssignment() const {
        if (!at(TokenKind::Identifier)) return false;
        TokenKind k = peekTok(1).kind;
        return k == TokenKind::Assign || k == TokenKind::PlusAssign ||
               k == TokenKind::MinusAssign || k == TokenKind::StarAssign ||
               k == TokenKind::SlashAssign;
    }

    StmtPtr assignment() {
        auto s = std::make_unique<Stmt>();
        s->kind = StmtKind::Assign;
        Token name = take();
        s->name = name.text;
        s->nameRange = name.range;
        Token op = take();
        switch (op.kind) {
        case TokenKind::PlusAssign:
            s->assignOp = AssignOp::Add;
            break;
        case TokenKind::MinusAssign:
            s->assignOp = AssignOp::Sub;
            break;
        case TokenKind::StarAssign:
            s->assignOp = AssignOp::Mul;
            break;
        case TokenKind::SlashAssign:
            s->assignOp = AssignOp::Div;
            break;
        default:
            s->assignOp = AssignOp::Set;
            break;
        }
        s->value = expression();
        s->range = SourceRange::span(name.range, previous().range);
        return s;
    }

    StmtPtr statement(bool topLevel) {
        DepthGuard guard(*this, cur().range);
        const Token start = cur();
        if (at(TokenKind::LBrace)) {
            auto s = std::make_unique<Stmt>();
            s->kind = StmtKind::Block;
            s->body = block();
            s->range = SourceRange::span(start.range, previous().range);
            return s;
        }
        if (accept(TokenKind::KwVar)) {
            if (!atAssignment())
                fail(cur().range, "expected a variable name and '=' after 'var'",
                     "write: var a = 1;");
            StmtPtr s = assignment();
            expect(TokenKind::Semicolon, "';' after the assignment");
            return s;
        }
        if (atAssignment()) {
            StmtPtr s = assignment();
            expect(TokenKind::Semicolon, "';' after the assignment");
            return s;
        }
        if (accept(TokenKind::KwIf)) {
            auto s = std::make_unique<Stmt>();
            s->kind = StmtKind::If;
            expect(TokenKind::LParen, "'(' after 'if'");
            s->value = expression();
            expect(TokenKind::RParen, "')' after the condition");
            s->body = blockOrStatement();
            if (accept(TokenKind::KwElse)) {
                s->hasElse = true;
                s->elseBody = blockOrStatement();
            }
            s->range = SourceRange::span(start.range, previous().range);
            return s;
        }
        if (accept(TokenKind::KwFor)) return forStatement(start);
        if (accept(TokenKind::KwReturn)) {
            auto s = std::make_unique<Stmt>();
            s->kind = StmtKind::Return;
            s->value = expression();
            expect(TokenKind::Semicolon, "';' after the returned value");
            s->range = SourceRange::span(start.range, previous().range);
            return s;
        }
        if (at(TokenKind::KwElse))
            fail(cur().range, "'else' without a matching 'if'", "remove it or add an 'if' before");
        auto s = std::make_unique<Stmt>();
        s->kind = StmtKind::ExprStmt;
        s->value = expression();
        s->range = SourceRange::span(start.range, previous().range);
        if (!accept(TokenKind::Semicolon) && !(topLevel && at(TokenKind::End))) {
            if (at(TokenKind::Assign) || at(TokenKind::EqualEqual))
                fail(cur().range, "only a plain name can be assigned to",
                     "assign to a local variable, for example: a = ...;");
            expect(TokenKind::Semicolon, "';' or an operator");
        }
        return s;
    }

    StmtPtr forStatement(const Token& start) {
        auto s = std::make_unique<Stmt>();
        s->kind = StmtKind::For;
        expect(TokenKind::LParen, "'(' after 'for'");
        accept(TokenKind::KwVar);
        Token var = expect(TokenKind::Identifier, "the loop variable",
                           "write: for (i = 0; i < 4; i++) { ... }");
        s->name = var.text;
        s->nameRange = var.range;
        expect(TokenKind::Assign, "'=' and the loop's first value");
        s->value = expression();
        expect(TokenKind::Semicolon, "';' after the loop's first value");
        s->condition = expression();
        expect(TokenKind::Semicolon, "';' after the loop condition");
        // step: i++ | i-- | i += e | i -= e | i = e
        Token stepName = expect(TokenKind::Identifier, "the loop step", "write: i++ or i += 1");
        auto step = std::make_unique<Stmt>();
        step->kind = StmtKind::Assign;
        step->name = stepName.text;
        step->nameRange = stepName.range;
        if ((at(TokenKind::Plus) || at(TokenKind::Minus)) && peekTok(1).kind == cur().kind) {
            bool up = at(TokenKind::Plus);
            Token first = take();
            take();
            step->assignOp = up ? AssignOp::Add : AssignOp::Sub;
            auto one = std::make_unique<Expr>();
            one->kind = ExprKind::Number;
            one->number = 1.0;
            one->range = first.range;
            step->value = std::move(one);
        } else if (at(TokenKind::Assign) || at(TokenKind::PlusAssign) ||
                   at(TokenKind::MinusAssign) || at(TokenKind::StarAssign) ||
                   at(TokenKind::SlashAssign)) {
            --pos_;
            step = assignment();
        } else {
            fail(cur().range, "expected the loop step but found " + found(),
                 "write: i++ or i += 1");
        }
        step->range = SourceRange::span(stepName.range, previous().range);
        s->step = std::move(step);
        expect(TokenKind::RParen, "')' after the loop step");
        s->body = blockOrStatement();
        s->range = SourceRange::span(start.range, previous().range);
        return s;
    }

    // ---- expressions --------------------------------------------------

    // Chains like 1+1+1+… deepen the tree without deepening the recursion,
    // so the tree's height is bounded here, where every node gets its children.
    void setDepth(Expr& e) {
        int d = 0;
        for (const ExprPtr& a : e.args)
            d = std::max(d, a->depth);
        e.depth = d + 1;
        if (e.depth > limits_.maxNestingDepth) {
            depthExceeded_ = true;
            fail(e.range,
                 "formula is nested too deeply (more than " +
                     std::to_string(limits_.maxNestingDepth) + " levels)",
                 "split it into named parts with local variables or functions");
        }
    }

    ExprPtr makeBinary(BinaryOp op, ExprPtr a, ExprPtr b) {
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Binary;
        e->binaryOp = op;
        e->range = SourceRange::span(a->range, b->range);
        e->args.push_back(std::move(a));
        e->args.push_back(std::move(b));
        setDepth(*e);
        return e;
    }

    ExprPtr expression() {
        DepthGuard guard(*this, cur().range);
        return ternary();
    }

    ExprPtr ternary() {
        ExprPtr cond = logicalOr();
        if (!at(TokenKind::Question)) return cond;
        DepthGuard guard(*this, cur().range);
        take();
        ExprPtr a = expression();
        expect(TokenKind::Colon, "':' in the conditional 'c ? a : b'");
        ExprPtr b = ternary();
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Ternary;
        e->range = SourceRange::span(cond->range, b->range);
        e->args.push_back(std::move(cond));
        e->args.push_back(std::move(a));
        e->args.push_back(std::move(b));
        setDepth(*e);
        return e;
    }

    template <typename Next>
    ExprPtr leftAssoc(Next next, std::initializer_list<std::pair<TokenKind, BinaryOp>> ops) {
        ExprPtr lhs = (this->*next)();
        for (;;) {
            bool matched = false;
            for (auto [tk, op] : ops) {
                if (at(tk)) {
                    DepthGuard guard(*this, cur().range);
                    take();
                    ExprPtr rhs = (this->*next)();
                    lhs = makeBinary(op, std::move(lhs), std::move(rhs));
                    matched = true;
                    break;
                }
            }
            if (!matched) break;
        }
        return lhs;
    }

    ExprPtr logicalOr() {
        return leftAssoc(&Parser::logicalAnd, {{TokenKind::OrOr, BinaryOp::Or}});
    }
    ExprPtr logicalAnd() {
        return leftAssoc(&Parser::setUnion, {{TokenKind::AndAnd, BinaryOp::And}});
    }
    ExprPtr setUnion() {
        return leftAssoc(&Parser::setIntersect, {{TokenKind::Pipe, BinaryOp::Union}});
    }
    ExprPtr setIntersect() {
        return leftAssoc(&Parser::equality, {{TokenKind::Amp, BinaryOp::Intersect},
                                             {TokenKind::Backslash, BinaryOp::Difference}});
    }
    ExprPtr equality() {
        return leftAssoc(&Parser::relational, {{TokenKind::EqualEqual, BinaryOp::Equal},
                                               {TokenKind::NotEqual, BinaryOp::NotEqual}});
    }
    ExprPtr relational() {
        return leftAssoc(&Parser::additive, {{TokenKind::Less, BinaryOp::Less},
                                             {TokenKind::LessEqual, BinaryOp::LessEqual},
                                             {TokenKind::Greater, BinaryOp::Greater},
                                             {TokenKind::GreaterEqual, BinaryOp::GreaterEqual}});
    }
    ExprPtr additive() {
        return leftAssoc(&Parser::multiplicative,
                         {{TokenKind::Plus, BinaryOp::Add}, {TokenKind::Minus, BinaryOp::Sub}});
    }
    ExprPtr multiplicative() {
        return leftAssoc(&Parser::unary,
                         {{TokenKind::Star, BinaryOp::Mul}, {TokenKind::Slash, BinaryOp::Div}});
    }

    ExprPtr unary() {
        UnaryOp op;
        if (at(TokenKind::Minus))
            op = UnaryOp::Negate;
        else if (at(TokenKind::Plus))
            op = UnaryOp::Plus;
        else if (at(TokenKind::Bang))
            op = UnaryOp::Not;
        else if (at(TokenKind::Tilde))
            op = UnaryOp::Complement;
        else
            return power();
        DepthGuard guard(*this, cur().range);
        Token t = take();
        ExprPtr operand = unary();
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Unary;
        e->unaryOp = op;
        e->range = SourceRange::span(t.range, operand->range);
        e->args.push_back(std::move(operand));
        setDepth(*e);
        return e;
    }

    // Power binds tighter than unary minus on its left (-x^2 = -(x^2)) and is
    // right-associative (2^3^2 = 2^9); its exponent may carry a sign (x^-2).
    ExprPtr power() {
        ExprPtr base = primary();
        if (!at(TokenKind::Caret)) return base;
        DepthGuard guard(*this, cur().range);
        take();
        ExprPtr exponent = unary();
        return makeBinary(BinaryOp::Pow, std::move(base), std::move(exponent));
    }

    ExprPtr primary() {
        const Token& t = cur();
        switch (t.kind) {
        case TokenKind::Number: {
            Token n = take();
            auto e = std::make_unique<Expr>();
            e->kind = ExprKind::Number;
            e->number = n.number;
            e->range = n.range;
            if (at(TokenKind::Identifier) || at(TokenKind::LParen)) {
                if (cur().range.begin.line > n.range.end.line) {
                    SourceRange where{n.range.end, n.range.end};
                    where.end.column += 1;
                    fail(where,
                         "expected ';' at the end of line " + std::to_string(n.range.end.line),
                         "add ';'");
                }
                fail(SourceRange::span(n.range, cur().range),
                     "a number is directly followed by " + found(),
                     "multiplication needs '*', for example 2*x");
            }
            return e;
        }
        case TokenKind::Identifier: {
            Token n = take();
            if (accept(TokenKind::LParen)) return call(n);
            auto e = std::make_unique<Expr>();
            e->kind = ExprKind::Name;
            e->name = n.text;
            e->range = n.range;
            return e;
        }
        case TokenKind::LParen: {
            Token open = take();
            ExprPtr inner = expression();
            expect(TokenKind::RParen, "')' to close the '(' opened at column " +
                                          std::to_string(open.range.begin.column));
            inner->range = SourceRange::span(open.range, previous().range);
            return inner;
        }
        case TokenKind::Invalid:
            throw SyntaxError{}; // already reported by the lexer
        default:
            break;
        }
        std::string hint;
        if (t.kind == TokenKind::End)
            hint = "the formula ends too early; complete the expression";
        else if (t.kind == TokenKind::RParen)
            hint = "there is a ')' without a matching '('";
        else
            hint = "write a number, a name or a parenthesised expression here";
        fail(t.range, "expected a value but found " + found(), hint);
    }

    ExprPtr call(const Token& name) {
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Call;
        e->name = name.text;
        e->nameRange = name.range;
        if (!at(TokenKind::RParen)) {
            do {
                e->args.push_back(expression());
            } while (accept(TokenKind::Comma));
        }
        expect(TokenKind::RParen, "')' to close the call of '" + name.text + "'",
               "add ')' or a ',' between arguments");
        e->range = SourceRange::span(name.range, previous().range);
        setDepth(*e);
        return e;
    }
};

} // namespace

Program parse(std::string_view source, std::vector<Diagnostic>& diagnostics, const Limits& limits) {
    if (source.size() > limits.maxSourceBytes) {
        diagnostics.push_back({Severity::Error,
                               {},
                               "formula is too long (" + std::to_string(source.size()) +
                                   " bytes; the limit is " + std::to_string(limits.maxSourceBytes) +
                                   ")",
                               "split it into smaller definitions"});
        return {};
    }
    std::vector<Token> tokens = tokenize(source, diagnostics);
    return Parser(std::move(tokens), diagnostics, limits).run();
}

} // namespace fl::formula
