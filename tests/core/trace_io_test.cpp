// The trace reader on hostile input (robustness review, issue 15): every field's type and every
// id's range is checked, and every failure is one TraceError line naming the file, line and key.
#include "raystep/trace/trace_io.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace raystep
