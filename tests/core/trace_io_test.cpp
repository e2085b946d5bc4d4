// The trace reader on hostile input (robustness review, issue 15): every field's type and every
// id's range is checked, and every failure is one TraceError line naming the file, line and key.
#include "raystep/trace/trace_io.h"

#include "raystep/trace/event_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raystep {
namespace {

/// The message of the TraceError `text` gives; a failure for no error or another exception type.
std::string traceErrorOf(const std::string& text) {
    try {
        traceFromJson(text, "t.json");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const TraceError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind("t.json:", 0), 0u) << what;
        return what;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a TraceError: " << e.what() << "\nfor: " << text;
    }
    return "";
}

const std::string kHead = "{\"format\": \"raystep-trace\", \"version\": 1,\n";
const std::string kRay =
    "{\"kind\": \"primary\", \"depth\": 0, \"parent\": null, \"origin\": [0, 0, 0],"
    " \"dir\": [0, 0, 1], \"t_min\": 0, \"t_max\": null}";
const std::string kNode = "{\"lo\": [0, 0, 0], \"hi\": [1, 1, 1]}";

/// A trace with one ray, one node and `events` (the events start on line 5).
std::string trace(const std::string& events, const std::string& extra = "") {
    return kHead + "\"rays\": [" + kRay + "],\n\"nodes\": [" + kNode + "]" + extra +
           ",\n\"events\": [\n" + events + "]}";
}

struct Case {
    std::string text;
    std::string expected;  // part of the message
};

TEST(TraceReader, EveryFieldsTypeAndEveryIdsRangeIsChecked) {
    const Case cases[] = {
        // Class 17: the header's fields, each with its type.
        {trace("", ",\n\"pixel\": \"x\""), "t.json:4: key 'pixel': expected [X, Y]"},
        {trace("", ",\n\"pixel\": [1]"), "t.json:4: key 'pixel': expected [X, Y]"},
        {trace("", ",\n\"pixel\": [1, \"a\"]"), "t.json:4: key 'pixel[1]': expected a whole"},
        {trace("", ",\n\"image\": {\"w\": 1}"), "t.json:4: key 'image': expected [W, H]"},
        {trace("", ",\n\"image\": [0, 5]"), "t.json:4: key 'image[0]': must be from 1"},
        {trace("", ",\n\"scene\": 5"), "t.json:4: key 'scene': expected a string"},
        {trace("", ",\n\"what\": null"), "t.json:4: key 'what': expected a string"},
        {trace("", ",\n\"accel\": []"), "t.json:4: key 'accel': expected a string"},
        {trace("", ",\n\"cap\": \"big\""), "t.json:4: key 'cap': expected a whole number"},
        {trace("", ",\n\"cap\": -1"), "t.json:4: key 'cap': must be from 0"},
        {trace("", ",\n\"dropped\": 1.5"), "t.json:4: key 'dropped': expected a whole number"},
        {kHead + "\"rays\": [],\n\"nodes\": [5],\n\"events\": []}",
         "t.json:3: key 'nodes[0]': expected an object"},
        {kHead + "\"rays\": [],\n\"nodes\": {},\n\"events\": []}",
         "t.json:3: key 'nodes': expected an array"},
        {kHead + "\"rays\": [\n5],\n\"events\": []}",
         "t.json:3: key 'rays[0]': expected an object"},
        // Ids point into their tables.
        {kHead + "\"rays\": [" + kRay + ",\n" + kRay.substr(0, kRay.find("null")) + "3" +
             kRay.substr(kRay.find("null") + 4) + "],\n\"events\": []}",
         "t.json:3: key 'rays[1].parent': ray 3 is not in 'rays' (2 rays)"},
        {trace("{\"type\": \"ray_begin\", \"ray\": 0, \"parent\": 4, \"kind\": \"primary\","
               " \"depth\": 0}"),
         "t.json:5: key 'events[0].parent': ray 4 is not in 'rays' (1 rays)"},
        {trace("{\"type\": \"build_node\", \"node\": 3, \"parent\": null, \"depth\": 0,"
               " \"prims\": 1}"),
         "t.json:5: key 'events[0].node': node 3 is not in 'nodes' (1 nodes)"},
        {trace("{\"type\": \"build_node\", \"node\": 0, \"parent\": 9, \"depth\": 0,"
               " \"prims\": 1}"),
         "t.json:5: key 'events[0].parent': node 9 is not in 'nodes' (1 nodes)"},
        {trace("{\"type\": \"node_enter\", \"ray\": 0, \"node\": 2, \"t_near\": 0,"
               " \"t_far\": 1}"),
         "t.json:5: key 'events[0].node': node 2 is not in 'nodes' (1 nodes)"},
        {trace("{\"type\": \"leaf_made\", \"node\": 1, \"reason\": \"max_depth\", \"prims\": 1,"
               " \"depth\": 0, \"leaf_cost\": 1}"),
         "t.json:5: key 'events[0].node': node 1 is not in 'nodes'"},
        {trace("{\"type\": \"split_chosen\", \"node\": 0, \"axis\": 3, \"position\": 0,"
               " \"sah_cost\": 1, \"leaf_cost\": 1}"),
         "t.json:5: key 'events[0].axis': must be from 0 to 2"},
        {trace("{\"type\": \"dda_cell\", \"ray\": 0, \"axes\": 8, \"cell\": [0, 0, 0],"
               " \"tMax\": [1, 1, 1]}"),
         "t.json:5: key 'events[0].axes': must be from 0 to 7"},
        {trace("{\"type\": \"dda_setup\", \"ray\": 0, \"dims\": 4, \"step\": [1, 1, 1],"
               " \"tDelta\": [1, 1, 1], \"t_enter\": 0, \"t_exit\": 1}"),
         "t.json:5: key 'events[0].dims': must be from 2 to 3"},
        {trace("{\"type\": \"dda_setup\", \"ray\": 0, \"dims\": 3, \"step\": [1, 2, 1],"
               " \"tDelta\": [1, 1, 1], \"t_enter\": 0, \"t_exit\": 1}"),
         "t.json:5: key 'events[0].step[1]': must be from -1 to 1"},
        {trace("5"), "t.json:5: key 'events[0]': expected an object"},
        // The added fields, when present, are checked as the others are.
        {trace("{\"type\": \"build_node\", \"node\": 0, \"parent\": null, \"depth\": 0,"
               " \"prims\": 1, \"c_isect\": \"x\", \"leaf_cost\": 5}"),
         "t.json:5: key 'events[0].c_isect': expected a number"},
        {trace("{\"type\": \"pixel_result\", \"x\": 8, \"y\": 0, \"width\": 8,"
               " \"height\": 6, \"rgb\": [0, 0, 0]}"),
         "t.json:5: key 'events[0].x': must be from 0 to 7"},
        {trace("{\"type\": \"pixel_result\", \"x\": 0, \"y\": 0, \"width\": null,"
               " \"height\": 6, \"rgb\": [0, 0, 0]}"),
         "t.json:5: key 'events[0].width': must be from 0 to 1048576"},
        {trace("{\"type\": \"ray_blocked\", \"ray\": 2, \"prim\": 0, \"t\": 1}"),
         "t.json:5: key 'events[0].ray': ray 2 is not in 'rays' (1 rays)"},
        // Every message has a line, a syntax error's too.
        {"{\"format\": \"raystep-trace\",\n\"version\": 1,,}", "t.json:2: malformed JSON"},
        {kHead + "\"rays\": [],\n\"events\": [\n{\"type\": \"ray_miss\",\n\"ray\": 1e999}]}",
         "t.json:5: number '1e999' is out of range"},
        // Class 4 and 11 in the trace reader.
        {kHead + "\"rays\": [],\n\"events\": " + std::string(100000, '[') +
             std::string(100000, ']') + "}",
         "t.json:3: nested deeper than 64 levels"},
        {kHead + "\"rays\": [],\n\"r\\u0061ys\": [],\n\"events\": []}",
         "t.json:3: key 'rays': key given twice"},
    };
    for (const Case& c : cases) {
        const std::string what = traceErrorOf(c.text);
        EXPECT_NE(what.find(c.expected), std::string::npos) << what << "\nfor: " << c.text;
    }
}

TEST(TraceReader, AValidTraceWithEveryHeaderFieldReadsBack) {
    const std::string text = trace(
        "{\"type\": \"ray_begin\", \"ray\": 0, \"parent\": null, \"kind\": \"primary\","
        " \"depth\": 0},\n"
        "{\"type\": \"node_enter\", \"ray\": 0, \"node\": 0, \"t_near\": 0, \"t_far\": null}",
        ",\n\"what\": \"pixel\", \"scene\": \"s\", \"accel\": \"kdtree sah\", \"pixel\": [3, 4],"
        " \"image\": [8, 6], \"cap\": 10, \"dropped\": 2");
    TraceInfo info;
    const EventLog log = traceFromJson(text, "t.json", &info);
    EXPECT_EQ(log.events().size(), 2u);
    EXPECT_EQ(log.cap(), 10u);
    EXPECT_EQ(log.dropped(), 2u);
    EXPECT_EQ(info.pixelX, 3);
    EXPECT_EQ(info.pixelY, 4);
    EXPECT_EQ(info.width, 8);
    EXPECT_EQ(info.height, 6);
    EXPECT_EQ(info.accel, "kdtree sah");
    // A pixel trace has no node table: its node ids cannot be checked against one.
    EXPECT_NO_THROW(traceFromJson(kHead + "\"rays\": [" + kRay +
                                      "],\n\"events\": [{\"type\": \"node_enter\", \"ray\": 0, "
                                      "\"node\": 7, \"t_near\": 0, \"t_far\": 1}]}",
                                  "t.json"));
}

TEST(TraceFile, TheAddedFieldsGoThroughTheFileBitForBit) {
    EventLog log;
    log.node(0, {0, 0, 0}, {1, 1, 0});
    log(BuildNode{0, kNoId, 0, 15, 20.0, 300.0});  // C_isect 20, 15 primitives: 300
    const std::uint32_t primary =
        log.beginRay(Ray{Vec3(0.0), Vec3(0, 0, 1)}, RayKind::Primary, 0, kNoId);
    const std::uint32_t shadow =
        log.beginRay(Ray{Vec3(0.0), Vec3(0, 1, 0), 0.0, 9.0}, RayKind::Shadow, 1, primary);
    log(PrimitiveTest{shadow, 4, true, 0.1 + 0.2});
    log(RayBlocked{shadow, 4, 0.1 + 0.2});  // a t with no short decimal: 0.30000000000000004
    log(PixelResult{3, 4, 8, 6, {0.25, 0.5, 1.0}});
    const std::string text = traceToJson(log, {});
    EXPECT_NE(text.find("\"prims\":15,\"c_isect\":20.0,\"leaf_cost\":300.0}"), std::string::npos)
        << text;
    EXPECT_NE(text.find("{\"type\":\"ray_blocked\",\"ray\":1,\"prim\":4,"
                        "\"t\":0.30000000000000004}"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\"x\":3,\"y\":4,\"width\":8,\"height\":6,"), std::string::npos) << text;
    const EventLog back = traceFromJson(text, "t.json");
    ASSERT_EQ(back.events().size(), log.events().size());
    const auto& b = std::get<BuildNode>(back.events()[0]);
    EXPECT_EQ(b.cIsect, 20.0);
    EXPECT_EQ(b.leafCost, 300.0);
    const auto& blocked = std::get<RayBlocked>(back.events()[4]);
    EXPECT_EQ(blocked.ray, shadow);
    EXPECT_EQ(blocked.prim, 4u);
    EXPECT_EQ(blocked.t, 0.1 + 0.2);
    const auto& pixel = std::get<PixelResult>(back.events()[5]);
    EXPECT_EQ(pixel.width, 8u);
    EXPECT_EQ(pixel.height, 6u);
    EXPECT_EQ(traceToJson(back, {}), text);
}

// A version-1 trace written before the added fields (docs/trace-format.md, "Versions"): a
// blocked shadow ray was a hit on no primitive at infinity, a build node had no leaf cost and a
// pixel no frame. It reads, and reads as a new trace says the same things.
TEST(TraceFile, ATraceWrittenBeforeTheAddedFieldsStillReads) {
    const std::string shadowRay =
        "{\"kind\": \"shadow\", \"depth\": 1, \"parent\": 0, \"origin\": [0, 0, 0],"
        " \"dir\": [0, 1, 0], \"t_min\": 0, \"t_max\": 9}";
    const std::string pixel =
        kHead + "\"what\": \"pixel\", \"pixel\": [3, 4], \"image\": [8, 6],\n" + "\"rays\": [" +
        kRay + ",\n" + shadowRay + "],\n\"events\": [\n" +
        "{\"type\":\"ray_begin\",\"ray\":0,\"parent\":null,\"kind\":\"primary\","
        "\"depth\":0},\n"
        "{\"type\":\"primitive_test\",\"ray\":0,\"prim\":2,\"hit\":true,\"t\":3},\n"
        "{\"type\":\"ray_hit\",\"ray\":0,\"prim\":2,\"t\":3,\"u\":0,\"v\":0},\n"
        "{\"type\":\"ray_begin\",\"ray\":1,\"parent\":0,\"kind\":\"shadow\",\"depth\":1},\n"
        "{\"type\":\"primitive_test\",\"ray\":1,\"prim\":6,\"hit\":false,\"t\":null},\n"
        "{\"type\":\"primitive_test\",\"ray\":1,\"prim\":4,\"hit\":true,\"t\":0.5},\n"
        "{\"type\":\"ray_hit\",\"ray\":1,\"prim\":null,\"t\":null,\"u\":0,\"v\":0},\n"
        "{\"type\":\"pixel_result\",\"x\":3,\"y\":4,\"rgb\":[0.25,0.5,1]}\n]}";
    const EventLog log = traceFromJson(pixel, "old.json");
    ASSERT_EQ(log.events().size(), 8u);
    // The primary ray's own hit stays a hit; the shadow ray's is what blocked it: the last test
    // of ray 1 that hit, primitive 4 at t = 0.5.
    EXPECT_EQ(std::get<RayHit>(log.events()[2]).prim, 2u);
    const auto* blocked = std::get_if<RayBlocked>(&log.events()[6]);
    ASSERT_TRUE(blocked);
    EXPECT_EQ(blocked->ray, 1u);
    EXPECT_EQ(blocked->prim, 4u);
    EXPECT_EQ(blocked->t, 0.5);
    EXPECT_EQ(eventText(log, 6),
              "shadow ray 1 blocked by primitive 4 at t = 0.5: the point is in shadow");
    EXPECT_EQ(eventText(log, 6, Language::It),
              "raggio d'ombra 1 bloccato dalla primitiva 4 a t = 0,5: il punto è in ombra");
    // The pixel's frame is the file's image.
    const auto& p = std::get<PixelResult>(log.events()[7]);
    EXPECT_EQ(p.width, 8u);
    EXPECT_EQ(p.height, 6u);
    // Written again, the trace says it the new way.
    const std::string again = traceToJson(log, {});
    EXPECT_EQ(again.find("\"prim\":null"), std::string::npos) << again;

    // A build: node 0 (4 primitives) split with leaf cost 20, so C_isect = 20 / 4 = 5; node 1
    // is empty (leaf cost 0: C_isect is the build's, 5); node 2's outcome is not in the file.
    const std::string build =
        kHead + "\"what\": \"build\",\n\"rays\": [],\n\"nodes\": [" + kNode + ", " + kNode + ", " +
        kNode + "],\n\"events\": [\n" +
        "{\"type\":\"build_node\",\"node\":0,\"parent\":null,\"depth\":0,\"prims\":4},\n"
        "{\"type\":\"split_candidate\",\"node\":0,\"axis\":0,\"position\":0.5,\"nl\":0,"
        "\"nr\":4,\"pl\":0.5,\"pr\":0.5,\"sah_cost\":6},\n"
        "{\"type\":\"split_chosen\",\"node\":0,\"axis\":0,\"position\":0.5,"
        "\"sah_cost\":6,\"leaf_cost\":20},\n"
        "{\"type\":\"build_node\",\"node\":1,\"parent\":0,\"depth\":1,\"prims\":0},\n"
        "{\"type\":\"leaf_made\",\"node\":1,\"reason\":\"few_primitives\",\"prims\":0,"
        "\"depth\":1,\"leaf_cost\":0},\n"
        "{\"type\":\"build_node\",\"node\":2,\"parent\":0,\"depth\":1,\"prims\":4}\n]}";
    const EventLog tree = traceFromJson(build, "old-build.json");
    ASSERT_EQ(tree.events().size(), 6u);
    const auto& root = std::get<BuildNode>(tree.events()[0]);
    EXPECT_EQ(root.leafCost, 20.0);
    EXPECT_EQ(root.cIsect, 5.0);
    const auto& empty = std::get<BuildNode>(tree.events()[3]);
    EXPECT_EQ(empty.leafCost, 0.0);
    EXPECT_EQ(empty.cIsect, 5.0);
    const auto& cut = std::get<BuildNode>(tree.events()[5]);
    EXPECT_TRUE(std::isnan(cut.leafCost));  // not known: no line rather than a wrong one
    EXPECT_EQ(cut.cIsect, 5.0);
}

}  // namespace
}  // namespace raystep
