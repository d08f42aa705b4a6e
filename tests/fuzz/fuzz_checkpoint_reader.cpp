// libFuzzer target for sbgen's checkpoint reader (issue 46): the bytes are read the way
// `sbgen --resume FILE` reads them before its first window (generator/main.cpp): readPacking,
// then the resume constructor of JammingProtocol, which reads the checkpoint's entries
// (readCheckpoint, protocol/checkpoint_entries.hpp), refuses overlaps and builds the engine, and
// the protocol's warnings. Every outcome must be a protocol or a refusal naming the file:
// PackingFileError or InvalidPacking from the packing reader, std::invalid_argument from the
// checkpoint's entries, any std::exception naming the file from the resume; never a crash, a
// hang, undefined behaviour or an allocation the file does not justify. The seed corpus is the
// checkpoints of tests/fuzz/seeds/ (scripts/fuzz.sh).
#include "fuzz_input.hpp"
#include "io/packing_io.hpp"
#include "protocol/checkpoint_entries.hpp"
#include "protocol/jamming_protocol.hpp"
#include "protocol/protocol_advice.hpp"

#include <cstdint>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = sbpack::fuzz::writeInput(data, size, "checkpoint.h5");
    const std::string source = path.string(), quoted = "'" + source + "'";
    std::optional<sbpack::Packing> packing;
    try {
        packing = sbpack::readPacking(path);
    } catch (const std::exception& e) {
        sbpack::fuzz::requirePackingRefusal(e, quoted, "readPacking");
        return 0;
    }
    try {
        sbpack::readCheckpoint(*packing, source);
    } catch (const std::invalid_argument& e) {
        sbpack::fuzz::requireNamed(e, quoted, "readCheckpoint");
        return 0;
    } catch (const std::exception& e) {
        sbpack::fuzz::finding("readCheckpoint: not std::invalid_argument", e);
    }
    try {
        const sbpack::JammingProtocol protocol(*packing, source);
        sbpack::protocolWarnings(protocol.parameters());
    } catch (const std::exception& e) {
        sbpack::fuzz::requireNamed(e, quoted, "the resume constructor");
    }
    return 0;
}
