#pragma once
// The one tool model every control's table format translates to and from.
//
// A Tool has one or more cutting edges (Sinumerik D numbers, Rockwell geometry/wear
// offsets, LinuxCNC's single entry per tool). All lengths are millimetres and all angles
// degrees, whatever unit the table file used; the table formats convert on read and write.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace toolcomp {

struct CuttingEdge {
    int number = 1;                      // D number / offset number (1 for single-edge tools)
    Eigen::Vector3d length{0, 0, 0};     // X Y Z offsets (tool length vector), mm
    std::array<double, 3> rotary{0, 0, 0};  // A B C offsets, degrees
    std::array<double, 3> uvw{0, 0, 0};  // U V W offsets, mm
    double radius = 0;                   // cutter/nose radius, mm (LinuxCNC D is the DIAMETER)
    double corner_radius = 0;            // R2, mm
    Eigen::Vector3d length_wear{0, 0, 0};  // wear deltas, added to length
    double radius_wear = 0;              // added to radius
    double corner_radius_wear = 0;       // added to corner_radius
    int orientation = 0;                 // lathe tip number 0-9 exactly as the table gives it
    double front_angle = 0;              // degrees
    double back_angle = 0;               // degrees

    Eigen::Vector3d effective_length() const;  // length + length_wear
    double effective_radius() const;           // radius + radius_wear
    double effective_corner_radius() const;    // corner_radius + corner_radius_wear

    friend bool operator==(const CuttingEdge& a, const CuttingEdge& b);
    friend bool operator!=(const CuttingEdge& a, const CuttingEdge& b) { return !(a == b); }
};

// The cutter shape from the radii (3D compensation): R2 = 0 end mill, R2 = R ball, between
// the two a toroid (bull nose).
enum class ToolShape { end_mill, toroid, ball };
ToolShape tool_shape(const CuttingEdge& e);

struct Tool {
    int number = 0;
    int pocket = 0;
    std::string name;
    std::string comment;
    std::vector<CuttingEdge> edges{CuttingEdge{}};  // at least one; edge numbers unique

    // The edge with D number `d`; throws ToolTableError("tool_no_such_edge") if absent.
    const CuttingEdge& edge(int d = 1) const;
    CuttingEdge& edge(int d = 1);
    bool has_edge(int d) const;
    // Insert or replace the edge with e.number (kept sorted by insertion order).
    void set_edge(const CuttingEdge& e);

    friend bool operator==(const Tool& a, const Tool& b);
    friend bool operator!=(const Tool& a, const Tool& b) { return !(a == b); }
};

// Throws ToolTableError when a tool cannot be stored in a table: no edges
// ("tool_no_edges"), a repeated edge number ("tool_duplicate_edge"), a negative tool or
// pocket number ("tool_bad_number"), an orientation outside 0..9 ("tool_bad_orientation").
void validate_tool(const Tool& t);

}  // namespace toolcomp
