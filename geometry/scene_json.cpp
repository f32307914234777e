// SPDX-License-Identifier: GPL-3.0-or-later
// Scene text to JSON (geometry/scene_json.h): the checks that come before any
// field is read (empty text, nesting depth, duplicate keys, JSON syntax), and
// the helpers that give every message its one-line "/pointer: what" shape.

#include "geometry/scene_json.h"

#include <algorithm>
#include <set>
#include <vector>

namespace hrs::geometry::scene_io {
namespace {

//! RFC 6901 escaping of one reference token.
std::string pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

//! Parser callback that rejects duplicate keys (a typo must not pass silently).
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const FieldReader& reader) : reader_(reader) {}

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        enter_value();
        frames_.push_back({true, {}, "", 0});
        break;
      case Json::parse_event_t::array_start:
        enter_value();
        frames_.push_back({false, {}, "", 0});
        break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        frames_.pop_back();
        break;
      case Json::parse_event_t::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) reader_.fail(pointer(), "duplicate field");
        break;
      }
      case Json::parse_event_t::value:
        enter_value();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;       //!< current key (objects)
    std::size_t next = 0;  //!< index of the next element (arrays)
  };

  //! A value starts inside the current container: advance the array index.
  void enter_value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().next;
  }

  std::string pointer() const {
    std::string ptr;
    for (const Frame& f : frames_) {
      ptr = f.object ? child(ptr, f.key) : child(ptr, f.next - 1);
    }
    return ptr;
  }

  const FieldReader& reader_;
  std::vector<Frame> frames_;
};

void reject_empty(std::string_view text, const FieldReader& errors) {
  if (std::all_of(text.begin(), text.end(),
                  [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; })) {
    errors.fail("", "empty file, expected a JSON object");
  }
}

//! The parser and the messages recurse into nested values: bound the depth
//! first, with a linear scan that cannot recurse.
void reject_deep_nesting(std::string_view text, const FieldReader& errors) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kDepth) {
        errors.fail("", "JSON nested deeper than " + std::to_string(limits::kDepth) +
                            " levels (limit of the format)");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      out += c == '\n' ? "\\n" : (c == '\t' ? "\\t" : "?");
    } else if (c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      out += '?';  // a C1 control (U+0080..U+009F), e.g. CSI
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string literal(std::string_view s) {
  return Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string shown(const Json& j) {
  std::string text = j.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(j.type_name()) + " " + text;
}

std::string num(double v) { return Json(v).dump(); }

std::string child(const std::string& ptr, std::string_view key) {
  return ptr + "/" + pointer_token(key);
}
std::string child(const std::string& ptr, std::size_t index) {
  return ptr + "/" + std::to_string(index);
}

Json parse_json(std::string_view text, const FieldReader& errors) {
  reject_empty(text, errors);
  reject_deep_nesting(text, errors);
  Json root;
  try {
    root = Json::parse(text.begin(), text.end(), DuplicateKeyCheck(errors));
  } catch (const Json::exception& e) {
    std::string what = e.what();
    if (const auto close = what.find("] ");
        what.rfind("[json.exception.", 0) == 0 && close != std::string::npos) {
      what = what.substr(close + 2);
    }
    errors.fail("", "invalid JSON: " + what);
  }
  return root;
}

}  // namespace hrs::geometry::scene_io
