#pragma once
// Syntax tree of a formula or script. Plain data: the parser builds it, the
// compiler walks it. Every node keeps its source range for diagnostics.
#include "source_range.h"

#include <memory>
#include <string>
#include <vector>

namespace fl::formula {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

enum class ExprKind { Number, Name, Unary, Binary, Ternary, Call };

enum class UnaryOp { Negate, Plus, Not, Complement };

enum class BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    Equal,
    NotEqual,
    And,
    Or,
    Intersect,
    Union,
    Difference,
};

struct Expr {
    ExprKind kind = ExprKind::Number;
    SourceRange range;
    double number = 0.0;   // Number
    std::string name;      // Name, Call (callee)
    SourceRange nameRange; // Call: the callee's name only
    UnaryOp unaryOp = UnaryOp::Negate;
    BinaryOp binaryOp = BinaryOp::Add;
    int depth = 1;             // height of this subtree, bounded by Limits::maxNestingDepth
    std::vector<ExprPtr> args; // operands: Unary 1, Binary 2, Ternary 3 (cond, then, else), Call n
};

struct Stmt;
using StmtPtr = std::unique_ptr<Stmt>;

enum class StmtKind { Assign, If, For, Return, Block, ExprStmt };

enum class AssignOp { Set, Add, Sub, Mul, Div };

struct Stmt {
    StmtKind kind = StmtKind::Block;
    SourceRange range;
    // Assign: target name; For: loop variable
    std::string name;
    SourceRange nameRange;
    AssignOp assignOp = AssignOp::Set;
    ExprPtr value; // Assign value, If condition, Return value, ExprStmt
    // For: init value in `value`, condition and step below
    ExprPtr condition;
    StmtPtr step;                  // For: the update, an Assign to the loop variable
    std::vector<StmtPtr> body;     // Block, For body, If then-branch
    std::vector<StmtPtr> elseBody; // If else-branch (may be empty)
    bool hasElse = false;
};

struct FunctionDecl {
    std::string name;
    SourceRange nameRange;
    SourceRange range;
    std::vector<std::string> params;
    std::vector<SourceRange> paramRanges;
    std::vector<StmtPtr> body;
};

// `param NAME = default in [lo, hi];` — a named, adjustable parameter.
struct ParamDecl {
    std::string name;
    SourceRange nameRange;
    SourceRange range;
    ExprPtr defaultValue; // constant expressions, checked by the compiler
    ExprPtr lo;           // null when no range was given
    ExprPtr hi;
};

struct Program {
    std::vector<FunctionDecl> functions;
    std::vector<ParamDecl> params;
    std::vector<StmtPtr> statements;
    // A bare expression program ("1 - x^2") is one ExprStmt; a script uses
    // assignments and return.
    bool isExpression = false;
};

} // namespace fl::formula
