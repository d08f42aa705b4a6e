#include "pipeline/record_bytes.hpp"

#include "pipeline/analysis_registry.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace sbpack {

namespace {

class Writer {
  public:
    template <class T> void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    void put(const std::string& text) {
        put(static_cast<std::uint64_t>(text.size()));
        bytes_ += text;
    }
    template <class T> void put(const std::vector<T>& values) {
        put(static_cast<std::uint64_t>(values.size()));
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    std::string take() { return std::move(bytes_); }

  private:
    std::string bytes_;
};

class Reader {
  public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <class T> T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        std::memcpy(&value, take(sizeof(T)), sizeof(T));
        return value;
    }
    std::string text() {
        const auto n = get<std::uint64_t>();
        return {take(n), n};
    }
    template <class T> std::vector<T> vector() {
        const auto n = get<std::uint64_t>();
        std::vector<T> values(n);
        if (n > 0) std::memcpy(values.data(), take(n * sizeof(T)), n * sizeof(T));
        return values;
    }
    bool done() const { return at_ == bytes_.size(); }

  private:
    const char* take(std::size_t n) {
        if (n > bytes_.size() - at_) throw std::logic_error("results bytes: truncated");
        const char* p = bytes_.data() + at_;
        at_ += n;
        return p;
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};

void putRecord(Writer& out, const schema::Record& record) {
    out.put(std::string(record.group().name));
    out.put(static_cast<std::uint64_t>(record.entries().size()));
    for (const schema::Entry& e : record.entries()) {
        out.put(std::string(e.field->name));
        out.put(static_cast<std::uint8_t>(e.value.index()));
        std::visit([&](const auto& v) { out.put(v); }, e.value);
    }
}

schema::Value getValue(Reader& in) {
    switch (in.get<std::uint8_t>()) {
    case 0:
        return in.get<double>();
    case 1:
        return in.get<std::int64_t>();
    case 2:
        return in.text();
    case 3:
        return in.vector<double>();
    case 4:
        return in.vector<std::int64_t>();
    default:
        throw std::logic_error("results bytes: unknown value type");
    }
}

schema::Record getRecord(Reader& in, const schema::Group& group) {
    schema::Record record(group);
    const auto entries = in.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < entries; ++i) {
        const std::string name = in.text();
        std::visit([&](auto&& v) { record.set(name, v); }, getValue(in));
    }
    return record;
}

const schema::Group& analysisGroup(const std::string& name) {
    const schema::Group* group = findResultGroup(name);
    if (group == nullptr) throw std::logic_error("results bytes: no group '" + name + "'");
    return *group;
}

} // namespace

std::string encodeFiles(const IndexedFiles& files) {
    Writer out;
    out.put(static_cast<std::uint64_t>(files.size()));
    for (const auto& [index, file] : files) {
        out.put(static_cast<std::uint64_t>(index));
        out.put(file.input.string());
        putRecord(out, file.root);
        out.put(file.sizeRatio);
        out.put(static_cast<std::uint64_t>(file.groups.size()));
        for (const schema::Record& g : file.groups)
            putRecord(out, g);
    }
    return out.take();
}

IndexedFiles decodeFiles(const std::string& bytes) {
    Reader in(bytes);
    IndexedFiles files(in.get<std::uint64_t>());
    for (auto& [index, file] : files) {
        index = in.get<std::uint64_t>();
        file.input = in.text();
        if (!in.text().empty()) throw std::logic_error("results bytes: not a file record");
        file.root = getRecord(in, schema::fileGroup());
        file.sizeRatio = in.get<double>();
        const auto groups = in.get<std::uint64_t>();
        for (std::uint64_t g = 0; g < groups; ++g) {
            const std::string name = in.text();
            file.groups.push_back(getRecord(in, analysisGroup(name)));
        }
    }
    if (!in.done()) throw std::logic_error("results bytes: trailing data");
    return files;
}

} // namespace sbpack
