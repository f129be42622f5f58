#pragma once
// The compiled form of a formula: a flat list of SSA-style instructions over a
// small register file. Registers 0..kInputCount-1 hold the coordinates x y z t
// u v w; parameters follow; temporaries are reused once dead, so a tape of
// thousands of instructions still runs in a few L1-resident registers.
#include "opcodes.h"
#include "source_range.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fl::formula {

enum class Input : std::uint8_t { X, Y, Z, T, U, V, W };
constexpr int kInputCount = 7;
constexpr std::array<const char*, kInputCount> kInputNames = {"x", "y", "z", "t", "u", "v", "w"};

// An instruction operand: a register or an immediate constant.
struct Operand {
    std::int32_t reg = -1; // -1: constant
    double value = 0.0;

    static Operand constant(double v) { return {-1, v}; }
    static Operand ofReg(std::int32_t r) { return {r, 0.0}; }
    bool isConst() const { return reg < 0; }
};

struct Instruction {
    Op op = Op::Add;
    std::int32_t out = 0;
    Operand a, b, c;
    double imm0 = 0.0;        // PowI exponent; R-function m
    double imm1 = 0.0;        // R-function alpha
    std::int32_t origin = -1; // index into Tape::origins: where in the source it came from
};

struct ParameterInfo {
    std::string name;
    std::int32_t reg = 0;
    double defaultValue = 0.0;
    bool hasRange = false;
    double lo = 0.0;
    double hi = 0.0;
};

struct OutputInfo {
    std::string name; // "value" for single-valued definitions, else "x", "r", "fx" …
    Operand value;
};

struct Tape {
    std::vector<Instruction> code;
    std::vector<SourceRange> origins;
    std::vector<ParameterInfo> params;
    std::vector<OutputInfo> outputs;
    std::int32_t registerCount = kInputCount;
    std::array<bool, kInputCount> usesInput{}; // which coordinates the formula reads

    std::int32_t paramRegister(const std::string& name) const {
        for (const ParameterInfo& p : params)
            if (p.name == name) return p.reg;
        return -1;
    }
    // Human-readable listing, one instruction per line (for `formula check --tape`).
    std::string disassemble() const;
};

} // namespace fl::formula
