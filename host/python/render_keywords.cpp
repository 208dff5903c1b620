// render_keywords.cpp — see render_keywords.h. A flag's kind is the type name
// the command line shows before its check ("UINT" of "UINT:in 1 to 16"):
// whole numbers, real numbers, paths, or text.
#include "python/render_keywords.h"

#include <algorithm>
#include <set>

#include "cli/cli.h"

namespace py = pybind11;

namespace wf {
namespace {

enum class Kind { Flag, Whole, Real, Path, Text };

Kind kind_of(const FlagInfo& f) {
    if (!f.takes_value) return Kind::Flag;
    const std::string base = f.type.substr(0, f.type.find(':'));
    if (base == "UINT" || base == "INT") return Kind::Whole;
    static const std::set<std::string> reals{"FLOAT", "EV", "L", "SECONDS", "X", "DEGREES"};
    if (reals.count(base)) return Kind::Real;
    static const std::set<std::string> paths{"OUT", "FILE", "DIR", "REF", "CSV", "PARTIAL"};
    if (paths.count(base)) return Kind::Path;
    return Kind::Text;
}

std::string keyword_of(std::string flag) {
    std::replace(flag.begin(), flag.end(), '-', '_');
    return flag;
}

const std::vector<FlagInfo>& flags() {
    static const std::vector<FlagInfo> list = render_flags();
    return list;
}

const FlagInfo* find_flag(const std::string& keyword) {
    for (const FlagInfo& f : flags())
        if (keyword_of(f.name) == keyword) return &f;
    return nullptr;
}

[[noreturn]] void wrong_type(const std::string& keyword, const std::string& wanted, py::handle value) {
    throw py::type_error("render(): " + keyword + " takes " + wanted + ", not " +
                         py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
}

bool is_bool(py::handle v) { return py::isinstance<py::bool_>(v); }
bool is_whole(py::handle v) { return !is_bool(v) && py::hasattr(v, "__index__"); } // int, NumPy's integers
bool is_real(py::handle v) { return !is_bool(v) && (is_whole(v) || py::hasattr(v, "__float__")); } // float, NumPy's
bool is_path(py::handle v) { return py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__"); }

std::string whole_word(py::handle v) { return py::str(py::int_(v.attr("__index__")())); }

bool is_list(py::handle v) { return py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v); }

// A list's items as one comma-separated word (aov=["albedo", "depth"]).
template <class Word> std::string comma_joined(py::handle list, const Word& word) {
    std::string joined;
    for (py::handle item : list) joined += (joined.empty() ? "" : ",") + word(item);
    return joined;
}

// device=: an index, a name ("cpu", "all"), a Device, or a list of those.
std::string device_word(const std::string& keyword, py::handle v) {
    if (py::hasattr(v, "index") && py::hasattr(v, "platform")) return py::str(v.attr("index"));
    if (is_whole(v)) return whole_word(v);
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    wrong_type(keyword, "a Device, an index, a name or a list of them", v);
}

std::string value_word(const FlagInfo& f, const std::string& keyword, py::handle v) {
    switch (kind_of(f)) {
    case Kind::Flag: break; // handled by the caller
    case Kind::Whole:
        if (is_whole(v)) return whole_word(v);
        // A bound that also takes a word (--max-depth unlimited).
        if (py::isinstance<py::str>(v) && f.type.find("or " + v.cast<std::string>()) != std::string::npos)
            return v.cast<std::string>();
        wrong_type(keyword, "an int", v);
    case Kind::Real:
        if (is_real(v)) return py::repr(py::float_(py::reinterpret_borrow<py::object>(v))).cast<std::string>();
        wrong_type(keyword, "a number", v);
    case Kind::Path:
        if (is_path(v)) return py::str(py::module_::import("os").attr("fspath")(v));
        wrong_type(keyword, "a str or os.PathLike", v);
    case Kind::Text:
        if (f.name == "device") {
            const auto device = [&](py::handle item) { return device_word(keyword, item); };
            return is_list(v) ? comma_joined(v, device) : device(v);
        }
        if (f.name == "look-at" && is_list(v)) // look_at=(eye..., target..., [up...])
            return comma_joined(v, [&](py::handle item) {
                if (!is_real(item)) wrong_type(keyword, "a list of numbers or a str", item);
                return py::repr(py::float_(py::reinterpret_borrow<py::object>(item))).cast<std::string>();
            });
        if (f.name == "aov" && is_list(v))
            return comma_joined(v, [&](py::handle item) {
                if (!py::isinstance<py::str>(item)) wrong_type(keyword, "a str or a list of str", item);
                return item.cast<std::string>();
            });
        if (py::isinstance<py::str>(v)) return v.cast<std::string>();
        wrong_type(keyword, "a str", v);
    }
    return "";
}

// The default a keyword shows: the help's "(default: X)" as a Python value
// where X is one (16, 0.5, 'group', False), else None, the command line's own
// default, which the help describes ("the first GPU, else the first device").
py::object default_value(const FlagInfo& f) {
    if (!f.takes_value) return py::bool_(false);
    const size_t at = f.help.rfind("(default: ");
    if (at == std::string::npos || f.help.back() != ')') return py::none();
    const std::string text = f.help.substr(at + 10, f.help.size() - at - 11);
    const Kind kind = kind_of(f);
    try {
        size_t used = 0;
        if (kind == Kind::Whole && text.find_first_not_of("0123456789") == std::string::npos)
            return py::int_(std::stoll(text));
        if (kind == Kind::Real) {
            const double value = std::stod(text, &used);
            if (used == text.size()) return py::float_(value);
        }
    } catch (const std::exception&) {
    }
    if (kind == Kind::Text && f.type.find("{") != std::string::npos) {
        const std::string choices = "," + f.type.substr(f.type.find('{') + 1);
        if (choices.find("," + text + ",") != std::string::npos || choices.find("," + text + "}") != std::string::npos)
            return py::str(text);
    }
    return py::none();
}

py::object annotation_of(const FlagInfo& f) {
    const py::module_ builtins = py::module_::import("builtins");
    switch (kind_of(f)) {
    case Kind::Flag: return builtins.attr("bool");
    case Kind::Whole: return builtins.attr("int");
    case Kind::Real: return builtins.attr("float");
    case Kind::Path: return py::module_::import("typing").attr("Union")[py::make_tuple(
                         builtins.attr("str"), py::module_::import("os").attr("PathLike"))];
    case Kind::Text: break;
    }
    return builtins.attr("str");
}

} // namespace

std::vector<std::string> render_words(const std::string& scene, const py::dict& keywords) {
    std::vector<std::string> words{"wavefront", "render", scene};
    for (const auto& [key, value] : keywords) {
        const std::string keyword = py::str(key);
        const FlagInfo* f = find_flag(keyword);
        if (!f) throw py::type_error("render() got an unexpected keyword argument '" + keyword + "'");
        if (value.is_none()) continue;
        if (!f->takes_value) {
            if (!is_bool(value)) wrong_type(keyword, "True or False", value);
            if (value.cast<bool>()) words.push_back("--" + f->name);
            continue;
        }
        words.push_back("--" + f->name);
        words.push_back(value_word(*f, keyword, value));
    }
    return words;
}

void describe_render(py::object function, const std::string& summary) {
    const py::module_ inspect = py::module_::import("inspect");
    const py::object Parameter = inspect.attr("Parameter");
    py::list parameters;
    parameters.append(Parameter("scene", Parameter.attr("POSITIONAL_OR_KEYWORD")));
    parameters.append(Parameter("progress", Parameter.attr("POSITIONAL_OR_KEYWORD"), py::arg("default") = py::none()));
    std::string doc = summary + "\n\nKeywords, one a flag of `wavefront render` (None: the flag's default):\n";
    for (const FlagInfo& f : flags()) {
        const std::string keyword = keyword_of(f.name);
        parameters.append(Parameter(keyword, Parameter.attr("KEYWORD_ONLY"), py::arg("default") = default_value(f),
                                    py::arg("annotation") = annotation_of(f)));
        doc += "    " + keyword + ": " + f.help + "\n";
    }
    function.attr("__signature__") = inspect.attr("Signature")(parameters);
    function.attr("__doc__") = doc;
}

} // namespace wf
