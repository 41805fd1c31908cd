// CRL syntax: a CastleMaker rule file (.rule, papers/castlemaker-crl.txt §3.6-3.7, ch. 5, §6.2)
// as read, before any meaning is given to it. readCrl() checks only the form (tokens, the shape of
// attrs, direct lots, rules and includes) and reports the first problem at file:line:column;
// crl_translate.cpp gives the functions their meaning.
#pragma once
#include <string>
#include <vector>

#include "grammar/translation.hpp"  // Location: a place in the user's file

namespace shapevo::crl {

enum class ArgKind { Number, Name, Rand, String };
/// One argument of a function: a number, an attr's name, rand(a, b) (bounds: numbers or attr
/// names) or a "string".
struct Arg {
    ArgKind kind = ArgKind::Number;
    double number = 0;      ///< Number
    std::string text;       ///< Name: the attr; String: its contents
    std::vector<Arg> bounds;  ///< Rand: lower and upper
    Location where;
};

struct Successor {
    std::string handle;
    Location where;
};

/// `[p] function(args) {Succ | ...}`: one function applied to a component.
struct Application {
    bool weighted = false;  ///< written with [p]
    double probability = 1;
    Location probabilityAt;
    std::string function;
    Location where;         ///< of the function's name
    std::vector<Arg> args;
    std::vector<Successor> successors;
};

/// `Handle = rect(...);` (direct: one application, no successors) or `Handle -> ...;` with one
/// application or several stochastic alternatives.
struct RuleDef {
    std::string predecessor;
    Location where;
    bool direct = false;
    std::vector<Application> alternatives;
};

struct Attr {
    std::string name;
    double value = 0;
    Location where;
};

struct Include {
    std::string path;  ///< as written, relative to the including file's folder
    Location where;
};

struct File {
    std::string path;
    std::vector<Attr> attrs;
    std::vector<RuleDef> rules;
    std::vector<Include> includes;
};

/// The syntax of a rule file. @throw InputError at path:line:column.
File readCrl(const std::string& text, const std::string& path);

}  // namespace shapevo::crl
