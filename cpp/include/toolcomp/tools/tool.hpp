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

/// One cutting edge (D number) of a tool. Lengths in mm, angles in degrees.
struct CuttingEdge {
    /// D number / offset number
    int number = 1;                      // D number / offset number (1 for single-edge tools)
    /// X Y Z tool length vector, mm (read-only float64 (3,) view; assign a new vector)
    Eigen::Vector3d length{0, 0, 0};     // X Y Z offsets (tool length vector), mm
    /// A B C offsets, degrees
    std::array<double, 3> rotary{0, 0, 0};
    /// U V W offsets, mm
    std::array<double, 3> uvw{0, 0, 0};
    /// cutter / nose radius, mm
    double radius = 0;                   // cutter/nose radius, mm (LinuxCNC D is the DIAMETER)
    /// corner radius R2, mm
    double corner_radius = 0;
    /// X Y Z wear, mm
    Eigen::Vector3d length_wear{0, 0, 0};  // wear deltas, added to length
    /// radius wear, mm, added to radius
    double radius_wear = 0;
    /// corner radius wear, mm, added to corner_radius
    double corner_radius_wear = 0;
    /// lathe tip number 0-9 as in the table
    int orientation = 0;                 // lathe tip number 0-9 exactly as the table gives it
    /// front angle, degrees
    double front_angle = 0;
    /// back angle, degrees
    double back_angle = 0;

    /// length + length_wear
    Eigen::Vector3d effective_length() const;
    /// radius + radius_wear
    double effective_radius() const;
    /// corner_radius + corner_radius_wear, mm
    double effective_corner_radius() const;

    friend bool operator==(const CuttingEdge& a, const CuttingEdge& b);
    friend bool operator!=(const CuttingEdge& a, const CuttingEdge& b) { return !(a == b); }
};

// The cutter shape from the radii (3D compensation): R2 = 0 end mill, R2 = R ball, between
// the two a toroid (bull nose).
enum class ToolShape { end_mill, toroid, ball };
ToolShape tool_shape(const CuttingEdge& e);

/// A tool with one or more cutting edges (values, not references into a table).
struct Tool {
    /// tool number (T), >= 0
    int number = 0;
    /// tool changer pocket number, >= 0
    int pocket = 0;
    /// tool name
    std::string name;
    /// comment text of the table entry
    std::string comment;
    /// the cutting edges (a tuple of copies; assign a new sequence to change them)
    std::vector<CuttingEdge> edges{CuttingEdge{}};  // at least one; edge numbers unique

    // The edge with D number `d`; throws ToolTableError("tool_no_such_edge") if absent.
    /// a copy of the edge with D number d
    const CuttingEdge& edge(int d = 1) const;
    CuttingEdge& edge(int d = 1);
    /// whether the tool has an edge with D number d
    bool has_edge(int d) const;
    // Insert or replace the edge with e.number (kept sorted by insertion order).
    /// insert or replace the edge with edge.number
    void set_edge(const CuttingEdge& e);

    friend bool operator==(const Tool& a, const Tool& b);
    friend bool operator!=(const Tool& a, const Tool& b) { return !(a == b); }
};

// Throws ToolTableError when a tool cannot be stored in a table: no edges
// ("tool_no_edges"), a repeated edge number ("tool_duplicate_edge"), a negative tool or
// pocket number ("tool_bad_number"), an orientation outside 0..9 ("tool_bad_orientation").
void validate_tool(const Tool& t);

}  // namespace toolcomp
