// A small JSON reader for the tests (the GLB writer's JSON chunk): objects, arrays, strings with
// the common escapes, numbers, true, false and null. parseJson() throws std::runtime_error on
// anything malformed, including text after the value other than white space, so a test that
// parses a chunk also proves that it is one well-formed JSON value.
#pragma once
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace shapevo::test {

struct Json {
    enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    bool has(const std::string& key) const { return type == Type::Object && object.count(key) > 0; }
    /// The member `key` of an object; throws if there is none.
    const Json& operator[](const std::string& key) const {
        if (!has(key)) throw std::runtime_error("JSON: no member '" + key + "'");
        return object.at(key);
    }
    /// Element `i` of an array; throws if there is none.
    const Json& operator[](std::size_t i) const {
        if (type != Type::Array || i >= array.size()) throw std::runtime_error("JSON: no element " + std::to_string(i));
        return array[i];
    }
    std::size_t size() const { return type == Type::Array ? array.size() : object.size(); }
};

namespace json_detail {

class Parser {
public:
    explicit Parser(const std::string& text) : s_(text) {}

    Json document() {
        Json v = value();
        space();
        if (at_ != s_.size()) fail("text after the value");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw std::runtime_error("JSON: " + why + " at byte " + std::to_string(at_));
    }
    void space() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\n' || s_[at_] == '\r' || s_[at_] == '\t')) ++at_;
    }
    char peek() {
        space();
        if (at_ >= s_.size()) fail("unexpected end");
        return s_[at_];
    }
    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++at_;
    }
    void word(const char* w) {
        for (const char* p = w; *p; ++p)
            if (at_ >= s_.size() || s_[at_++] != *p) fail(std::string("expected ") + w);
    }
    std::string stringValue() {
        expect('"');
        std::string out;
        while (true) {
            if (at_ >= s_.size()) fail("unterminated string");
            const char c = s_[at_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (at_ >= s_.size()) fail("unterminated escape");
            const char e = s_[at_++];
            switch (e) {
                case '"': case '\\': case '/': out += e; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                default: fail("unsupported escape");  // \u is not needed by these tests
            }
        }
    }
    Json value() {
        Json v;
        const char c = peek();
        if (c == '{') {
            v.type = Json::Type::Object;
            ++at_;
            if (peek() == '}') return ++at_, v;
            while (true) {
                std::string key = stringValue();
                expect(':');
                if (!v.object.emplace(key, value()).second) fail("duplicate key '" + key + "'");
                if (peek() == ',') ++at_;
                else return expect('}'), v;
            }
        }
        if (c == '[') {
            v.type = Json::Type::Array;
            ++at_;
            if (peek() == ']') return ++at_, v;
            while (true) {
                v.array.push_back(value());
                if (peek() == ',') ++at_;
                else return expect(']'), v;
            }
        }
        if (c == '"') {
            v.type = Json::Type::String;
            v.string = stringValue();
            return v;
        }
        if (c == 't' || c == 'f') {
            v.type = Json::Type::Bool;
            v.boolean = c == 't';
            word(v.boolean ? "true" : "false");
            return v;
        }
        if (c == 'n') return word("null"), v;
        const char* begin = s_.c_str() + at_;
        char* end = nullptr;
        v.type = Json::Type::Number;
        v.number = std::strtod(begin, &end);
        if (end == begin) fail("expected a value");
        at_ += std::size_t(end - begin);
        return v;
    }

    const std::string& s_;
    std::size_t at_ = 0;
};

}  // namespace json_detail

inline Json parseJson(const std::string& text) { return json_detail::Parser(text).document(); }

}  // namespace shapevo::test
