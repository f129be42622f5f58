#pragma once
// Modelling commands typed in the chat (docs/classroom-protocol.md, "Chat
// commands"). A chat text that starts with '/' is a command: parsed here,
// turned into a new scene text here, and then applied by the class through
// the same path as an edit (lock, checks, log, broadcast). The command works
// on "the class shape": the FShape named CLASS (DEF), else the first FShape
// of the scene; /add makes one when the scene has none.
#include <optional>
#include <string>
#include <string_view>

namespace fl::classroom {

enum class ChatCommandKind { Help, Add, Paint, Undo, Save };
enum class ShapeOperation { Union, Intersection, Difference };

struct Colour {
    double r = 0, g = 0, b = 0;
};

struct ChatCommand {
    ChatCommandKind kind = ChatCommandKind::Help;
    ShapeOperation operation = ShapeOperation::Union; // Add
    std::string formula;                              // Add, Paint: the tool's shape, f >= 0 inside
    Colour colour;                                    // Paint
    double opacity = 1;                               // Paint: 0 keeps the colour, 1 replaces it
    std::string label;                                // Save
};

struct ChatCommandParse {
    std::optional<ChatCommand> command;
    std::string error; // why not, with the usage
};

bool isChatCommand(std::string_view text);
ChatCommandParse parseChatCommand(std::string_view text);

// The text /help answers with.
std::string chatCommandHelp();

// A syntax mistake in the formula of an Add or Paint, located in what the
// student typed (column 18 of the command), not in the class scene the
// formula would be combined into. `text` is the command as typed. A parse
// only: cheap enough for the server's event loop (the class checks the
// combined scene in full, off it).
struct CommandMistake {
    std::size_t column = 0; // characters, from 1, in the command text
    std::string message;
    std::string suggestion;
    std::string said() const; // "column 18 of your command: ..."
};
std::optional<CommandMistake> formulaMistakeInCommand(const ChatCommand& command,
                                                      std::string_view text);

// The scene text after Add or Paint; empty with `why` when the scene has no
// shape the command can work on. The result is not yet checked: the class
// checks it like any edit.
std::string applyChatCommand(const ChatCommand& command, const std::string& sceneText,
                             std::string& why);

} // namespace fl::classroom
