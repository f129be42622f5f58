#include "field_type.h"

#include <array>

namespace fl::scene {
namespace {

constexpr std::array<std::string_view, static_cast<int>(FieldType::Unknown) + 1> kTypeNames = {
    "SFBool",      "SFInt32", "SFFloat",    "SFDouble",   "SFTime",     "SFString",   "SFVec2f",
    "SFVec2d",     "SFVec3f", "SFVec3d",    "SFVec4f",    "SFVec4d",    "SFRotation", "SFColor",
    "SFColorRGBA", "SFImage", "SFMatrix3f", "SFMatrix3d", "SFMatrix4f", "SFMatrix4d", "SFNode",
    "MFBool",      "MFInt32", "MFFloat",    "MFDouble",   "MFTime",     "MFString",   "MFVec2f",
    "MFVec2d",     "MFVec3f", "MFVec3d",    "MFVec4f",    "MFVec4d",    "MFRotation", "MFColor",
    "MFColorRGBA", "MFImage", "MFMatrix3f", "MFMatrix3d", "MFMatrix4f", "MFMatrix4d", "MFNode",
    "Unknown",
};

constexpr int kFirstMultiple = static_cast<int>(FieldType::MFBool);
constexpr int kSingleCount = kFirstMultiple; // SFBool..SFNode

} // namespace

std::string_view fieldTypeName(FieldType type) {
    return kTypeNames[static_cast<int>(type)];
}

std::optional<FieldType> parseFieldType(std::string_view name) {
    for (int i = 0; i < static_cast<int>(FieldType::Unknown); ++i)
        if (kTypeNames[i] == name) return static_cast<FieldType>(i);
    return std::nullopt;
}

std::string_view accessTypeName(AccessType access) {
    switch (access) {
    case AccessType::InitializeOnly:
        return "initializeOnly";
    case AccessType::InputOnly:
        return "inputOnly";
    case AccessType::OutputOnly:
        return "outputOnly";
    case AccessType::InputOutput:
        return "inputOutput";
    }
    return "initializeOnly";
}

std::string_view vrml97AccessTypeName(AccessType access) {
    switch (access) {
    case AccessType::InitializeOnly:
        return "field";
    case AccessType::InputOnly:
        return "eventIn";
    case AccessType::OutputOnly:
        return "eventOut";
    case AccessType::InputOutput:
        return "exposedField";
    }
    return "field";
}

std::optional<AccessType> parseAccessType(std::string_view name) {
    if (name == "initializeOnly" || name == "field") return AccessType::InitializeOnly;
    if (name == "inputOnly" || name == "eventIn") return AccessType::InputOnly;
    if (name == "outputOnly" || name == "eventOut") return AccessType::OutputOnly;
    if (name == "inputOutput" || name == "exposedField") return AccessType::InputOutput;
    return std::nullopt;
}

bool isMultiple(FieldType type) {
    return static_cast<int>(type) >= kFirstMultiple && type != FieldType::Unknown;
}

FieldType singleOf(FieldType type) {
    if (!isMultiple(type)) return type;
    return static_cast<FieldType>(static_cast<int>(type) - kSingleCount);
}

bool holdsNodes(FieldType type) {
    return singleOf(type) == FieldType::SFNode;
}
bool holdsStrings(FieldType type) {
    return singleOf(type) == FieldType::SFString;
}

bool isIntegral(FieldType type) {
    const FieldType s = singleOf(type);
    return s == FieldType::SFBool || s == FieldType::SFInt32 || s == FieldType::SFImage;
}

int componentsPerElement(FieldType type) {
    switch (singleOf(type)) {
    case FieldType::SFBool:
    case FieldType::SFInt32:
    case FieldType::SFFloat:
    case FieldType::SFDouble:
    case FieldType::SFTime:
        return 1;
    case FieldType::SFVec2f:
    case FieldType::SFVec2d:
        return 2;
    case FieldType::SFVec3f:
    case FieldType::SFVec3d:
    case FieldType::SFColor:
        return 3;
    case FieldType::SFVec4f:
    case FieldType::SFVec4d:
    case FieldType::SFRotation:
    case FieldType::SFColorRGBA:
        return 4;
    case FieldType::SFMatrix3f:
    case FieldType::SFMatrix3d:
        return 9;
    case FieldType::SFMatrix4f:
    case FieldType::SFMatrix4d:
        return 16;
    default:
        return 0;
    }
}

bool canRead(AccessType a) {
    return a == AccessType::OutputOnly || a == AccessType::InputOutput;
}
bool canWrite(AccessType a) {
    return a == AccessType::InputOnly || a == AccessType::InputOutput;
}
bool hasInitialValue(AccessType a) {
    return a == AccessType::InitializeOnly || a == AccessType::InputOutput;
}

} // namespace fl::scene
