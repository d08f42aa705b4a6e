// The checkpoint's one table (protocol/checkpoint_entries.hpp): every entry the resume reads is
// required or has a default, a checkpoint resumes to the same entries, and out-of-range or
// missing state is refused naming its group and key.
#include "protocol/checkpoint_entries.hpp"
#include "protocol/jamming_protocol.hpp"
#include "small_runs.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace sbpack {
namespace {

/// A checkpoint of a short superball run (the rotating engine: predictor counters included) with
/// a finish (its entries are written only where there is one).
Packing shortSuperballCheckpoint() {
    ProtocolParameters p = testing::smallRun(1);
    p.particles = 27;
    p.shape = sbpack::ShapeSpec::superball(1.5);
    p.pressureSwitch = 1e2;
    p.pressureFinal = 1e4;
    p.pressureFinish = 1e3;
    p.finishSpeed = 2.0;
    return testing::finishedCheckpoint(p);
}

std::map<std::string, ProvenanceValue>& groupOf(Packing& packing, const std::string& group) {
    return group == "provenance" ? packing.provenance : packing.resumeState;
}

/// The message of resuming `packing`, empty if it resumes.
std::string refusal(const Packing& packing) {
    try {
        JammingProtocol resumed(packing, "edited.h5");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

/// A checkpoint of a short binary sphere run (docs/mixtures.md: its entries are written only by a
/// mixture's run).
Packing shortMixtureCheckpoint() {
    ProtocolParameters p = testing::smallRun(1);
    p.particles = 40;
    p.sizeRatio = 1.4;
    p.pressureSwitch = 1e2;
    p.pressureFinal = 1e3;
    return testing::finishedCheckpoint(p);
}

TEST(CheckpointEntries, EveryKeyIsWrittenOnceAndResumesToTheSameEntries) {
    const Packing written = shortSuperballCheckpoint(), mixture = shortMixtureCheckpoint();
    const std::set<std::string> mixtureKeys = {"size_ratio", "large_fraction", "polydispersity"};
    // Written only by a run raised at a plateau (StiffJamming.APlateauWhoseCheckSaysJammed...).
    const std::set<std::string> plateauKeys = {"stall_speed"};
    std::set<std::string> seen;
    for (const CheckpointKey& k : checkpointKeys()) {
        EXPECT_TRUE(seen.insert(k.group + "/" + k.key).second) << k.key << " declared twice";
        if (plateauKeys.contains(k.key)) continue;
        Packing copy = mixtureKeys.contains(k.key) ? mixture : written;
        EXPECT_EQ(groupOf(copy, k.group).count(k.key), 1u) << k.group << " " << k.key;
    }
    EXPECT_EQ(seen.size(), written.provenance.size() + written.resumeState.size() +
                               mixtureKeys.size() + plateauKeys.size());
    const Packing mixtureAgain = JammingProtocol(mixture, "mixture.h5").checkpoint();
    EXPECT_EQ(mixtureAgain.provenance, mixture.provenance);
    const Packing again = JammingProtocol(written, "written.h5").checkpoint();
    EXPECT_EQ(again.provenance, written.provenance);
    EXPECT_EQ(again.resumeState, written.resumeState);
}

TEST(CheckpointEntries, AMissingRequiredEntryIsRefusedByNameAndAMissingOptionalOneDefaults) {
    const Packing written = shortSuperballCheckpoint();
    int required = 0;
    for (const CheckpointKey& k : checkpointKeys()) {
        if (!k.read) continue;
        Packing edited = written;
        groupOf(edited, k.group).erase(k.key);
        if (k.key == "pressure_finish") // a finish speed without its pressure is refused
            groupOf(edited, k.group).erase("finish_speed");
        const std::string message = refusal(edited);
        if (k.optional) {
            EXPECT_EQ(message, "") << k.key;
            continue;
        }
        ++required;
        EXPECT_NE(message.find("'edited.h5': not an sbgen checkpoint (" + k.group + " '" + k.key +
                               "' missing"),
                  std::string::npos)
            << message;
        if (k.key == "format") continue; // a string either way: its value is checked below
        groupOf(edited, k.group)[k.key] = std::string("wrong type");
        EXPECT_NE(refusal(edited).find("of the wrong type"), std::string::npos) << k.key;
    }
    EXPECT_GE(required, 15);
}

TEST(CheckpointEntries, APhaseOutOfRangeOrANegativeCounterIsRefused) {
    Packing edited = shortSuperballCheckpoint();
    edited.resumeState["phase"] = std::int64_t{5}; // would never reach its end
    EXPECT_NE(refusal(edited).find("checkpoint state phase is 5, not 0 (fast), 1 (slow) or 2"),
              std::string::npos)
        << refusal(edited);
    edited = shortSuperballCheckpoint();
    edited.provenance["collisions"] = std::int64_t{-1};
    EXPECT_NE(refusal(edited).find("checkpoint entry 'collisions' is negative"), std::string::npos)
        << refusal(edited);
    edited = shortSuperballCheckpoint();
    edited.provenance["stall_speed"] = 0.5; // a plateau's raise never slows the growth
    EXPECT_NE(refusal(edited).find("'stall_speed' must be at least 1"), std::string::npos)
        << refusal(edited);
    edited = shortSuperballCheckpoint();
    edited.resumeState["format"] = std::string("sbgen.state/0");
    EXPECT_NE(refusal(edited).find("checkpoint state format is not sbgen.state/1"),
              std::string::npos);
}

} // namespace
} // namespace sbpack
