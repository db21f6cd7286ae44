#include "sweep/config/json_file.hpp"

#include "sweep/format.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "sweep/errors.hpp"

namespace wirepack::sweep {

using json = nlohmann::json;

std::string pointer_child(const std::string& parent, const std::string& key) {
  std::string out = parent + "/";
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

namespace {

// SAX handler that builds the document like nlohmann's own DOM parser, but knows the JSON
// pointer of the value being read, so duplicate keys and overflowing numbers can be named.
class StrictSax : public nlohmann::json_sax<json> {
 public:
  explicit StrictSax(std::string source) : source_(std::move(source)) {}

  bool null() override { return add(json(nullptr)); }
  bool boolean(bool v) override { return add(json(v)); }
  bool number_integer(number_integer_t v) override { return add(json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add(json(v)); }
  bool number_float(number_float_t v, const string_t&) override { return add(json(v)); }
  bool string(string_t& v) override { return add(json(v)); }
  bool binary(binary_t& v) override { return add(json(v)); }

  bool start_object(std::size_t) override {
    json* obj = insert(json::object());
    stack_.push_back({obj, ""});
    return true;
  }
  bool key(string_t& k) override {
    Frame& f = stack_.back();
    f.key = k;
    if (f.node->contains(k)) errors_.push_back(source_ + ": " + pointer() + ": duplicate key");
    return true;
  }
  bool end_object() override {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    json* arr = insert(json::array());
    stack_.push_back({arr, ""});
    return true;
  }
  bool end_array() override {
    stack_.pop_back();
    return true;
  }

  bool parse_error(std::size_t, const std::string& token,
                   const nlohmann::detail::exception& e) override {
    if (e.id == 406) {
      // out_of_range.406: a number too large for a double (it would be +-inf).
      errors_.push_back(source_ + ": " + pointer() + ": must be a finite number (got " + token +
                        ", which overflows a double)");
    } else {
      // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> keep the
      // part from "line" on.
      std::string what = e.what();
      const auto at = what.find(" at line ");
      errors_.push_back(source_ + ": " + (at == std::string::npos ? what : what.substr(at + 4)));
    }
    return false;
  }

  json& result() { return root_; }
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  struct Frame {
    json* node;       // the container being filled
    std::string key;  // last key read (objects)
  };

  // Places a value in the current container (or as the root) and returns it.
  json* insert(json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = stack_.back();
    if (f.node->is_array()) {
      f.node->push_back(std::move(v));
      return &f.node->back();
    }
    (*f.node)[f.key] = std::move(v);
    return &(*f.node)[f.key];
  }
  bool add(json&& v) {
    insert(std::move(v));
    return true;
  }
  // Pointer of the value being read: object frames contribute their last key, array frames
  // the index of the element in progress (the last one for enclosing frames).
  std::string pointer() const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      if (f.node->is_array()) {
        std::size_t idx = f.node->size();
        if (i + 1 < stack_.size() && idx > 0) --idx;
        p += '/';
        p += std::to_string(idx);
      } else {
        p = pointer_child(p, f.key);
      }
    }
    return p.empty() ? "/" : p;
  }

  std::string source_;
  json root_;
  std::vector<Frame> stack_;
  std::vector<std::string> errors_;
};

}  // namespace

json parse_json_text(const std::string& text, const std::string& source,
                     std::vector<std::string>* soft_errors) {
  StrictSax sax(source);
  const bool ok = json::sax_parse(text, &sax);
  if (!ok) {
    auto errors = sax.errors();
    if (errors.empty()) errors.push_back(source + ": invalid JSON");
    throw InputError(errors);
  }
  if (!sax.errors().empty()) {
    if (!soft_errors) throw InputError(sax.errors());
    soft_errors->insert(soft_errors->end(), sax.errors().begin(), sax.errors().end());
  }
  return std::move(sax.result());
}

json load_json_file(const std::string& path, std::vector<std::string>* soft_errors) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read file");
  return parse_json_text(text.str(), path, soft_errors);
}

std::string describe_value(const nlohmann::json& v) {
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_number_float()) return format_number(v.get<double>());
  std::string s = v.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

}  // namespace wirepack::sweep
