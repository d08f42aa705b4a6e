#include "schema/record.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <variant>

namespace sbpack::schema {

namespace {

std::string where(const Group& group, std::string_view name) {
    return "results schema: " + std::string(group.path) + "/" + std::string(name);
}

/// Which alternative of Value a field holds.
std::size_t valueIndex(const Field& f) {
    if (f.type == Type::String) return 2;
    if (f.kind == Kind::Attribute) return f.type == Type::Float ? 0 : 1;
    return f.type == Type::Float ? 3 : 4;
}

/// The values of a dataset (an attribute: 1).
std::size_t flatSize(const Value& value) {
    if (const auto* v = std::get_if<std::vector<double>>(&value)) return v->size();
    if (const auto* v = std::get_if<std::vector<std::int64_t>>(&value)) return v->size();
    return 1;
}

/// The required fields of `group` that `entries` (in the schema's order) lack.
std::string missingFields(const Group& group, const std::vector<Entry>& entries) {
    std::string missing;
    auto set = entries.begin();
    for (const Field& f : group.fields) {
        if (set != entries.end() && set->field == &f) {
            ++set;
            continue;
        }
        if (!f.optional) missing += (missing.empty() ? "" : ", ") + std::string(f.name);
    }
    return missing;
}

} // namespace

const std::vector<Entry>& Record::entries() const {
    const std::string missing = missingFields(*group_, entries_);
    if (!missing.empty())
        throw std::logic_error("results schema: " + std::string(group_->path) +
                               ": required fields not set: " + missing);
    return entries_;
}

const Field& Record::field(std::string_view name) const {
    const Field* f = findField(*group_, name);
    if (f == nullptr) throw std::logic_error(where(*group_, name) + " is not declared");
    return *f;
}

Record& Record::store(const Field& field, Value value) {
    if (value.index() != valueIndex(field))
        throw std::logic_error(where(*group_, field.name) + ": value of the wrong kind or type");
    if (field.width > 0 && flatSize(value) % static_cast<std::size_t>(field.width) != 0)
        throw std::logic_error(where(*group_, field.name) + ": not rows of " +
                               std::to_string(field.width) + " values");
    // Keep the schema's order: insert before the first entry declared after this field.
    auto at = entries_.begin();
    while (at != entries_.end() && at->field < &field)
        ++at;
    if (at != entries_.end() && at->field == &field)
        at->value = std::move(value);
    else
        entries_.insert(at, Entry{&field, std::move(value)});
    return *this;
}

Record& Record::set(const Field& field, Value value) {
    const std::span<const Field> own = group_->fields;
    const std::less<const Field*> before;
    if (own.empty() || before(&field, own.data()) || !before(&field, own.data() + own.size()))
        throw std::logic_error(where(*group_, field.name) + " is not one of the group's fields");
    if (field.type == Type::Float && std::holds_alternative<std::int64_t>(value))
        value = static_cast<double>(std::get<std::int64_t>(value));
    return store(field, std::move(value));
}

const Value* Record::find(std::string_view name) const {
    for (const Entry& e : entries_)
        if (e.field->name == name) return &e.value;
    return nullptr;
}

template <class T> const T& Record::get(std::string_view name) const {
    const Value* v = find(name);
    if (v == nullptr) throw std::logic_error(where(*group_, name) + " was not set");
    if (const T* typed = std::get_if<T>(v)) return *typed;
    throw std::logic_error(where(*group_, name) + " has another type");
}

double Record::number(std::string_view name) const {
    const Value* v = find(name);
    if (v != nullptr && std::holds_alternative<std::int64_t>(*v))
        return static_cast<double>(std::get<std::int64_t>(*v));
    return get<double>(name);
}
std::int64_t Record::integer(std::string_view name) const {
    return get<std::int64_t>(name);
}
const std::string& Record::text(std::string_view name) const {
    return get<std::string>(name);
}
const std::vector<double>& Record::floats(std::string_view name) const {
    return get<std::vector<double>>(name);
}
const std::vector<std::int64_t>& Record::integers(std::string_view name) const {
    return get<std::vector<std::int64_t>>(name);
}

} // namespace sbpack::schema
