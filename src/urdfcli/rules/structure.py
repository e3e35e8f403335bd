"""Structural rules: emitted while a description is read and its tree built.

Everything check_urdf rejects is here (``urdfdom=True``), plus the defects
that make a description unusable which check_urdf does not see.
"""

from . import ERROR, WARNING, declare

U = dict(urdfdom=True)

# Input
declare("X001", "xml-syntax-error", ERROR, "The file is not well-formed XML.", **U)
declare("X002", "xml-entity-declaration", ERROR, "The document declares XML entities, which urdfcli never expands.")
declare("X003", "xacro-error", ERROR, "xacro could not expand the file.")
declare("X004", "package-not-found", ERROR, "A `$(find pkg)` names a package that cannot be found.")
declare("X005", "xacro-warning", WARNING, "xacro warned while expanding the file.")

# Robot
declare("R001", "robot-element-missing", ERROR, "The root element is not `<robot>`.", **U)
declare("R002", "robot-name-missing", ERROR, "`<robot>` has no `name` attribute.", **U)
declare("R003", "robot-version-unsupported", ERROR, "`<robot version>` is not `1.0`.", **U)
declare("R004", "robot-without-links", ERROR, "The robot has no `<link>`.", **U)

# Names
declare("N001", "link-name-missing", ERROR, "A `<link>` has no `name`.", **U)
declare("N002", "joint-name-missing", ERROR, "A `<joint>` has no `name`.", **U)
declare("N003", "material-name-missing", ERROR, "A `<material>` has no `name`.", **U)
declare("N004", "duplicate-link", ERROR, "Two links have the same name.", **U)
declare("N005", "duplicate-joint", ERROR, "Two joints have the same name.", **U)
declare("N006", "duplicate-material", ERROR, "Two top-level materials have the same name.", **U)

# Values
declare("V001", "number-malformed", ERROR, "A number that urdfdom cannot read.", **U)
declare("V002", "number-not-finite", ERROR, "A number that is NaN, infinite or overflows.", **U)
declare("V003", "vector-length", ERROR, "A vector (`xyz`, `rpy`, `size`, `scale`) without three components.", **U)
declare("V004", "attribute-missing", ERROR, "A required attribute is missing.", **U)
declare("V005", "element-missing", ERROR, "A required child element is missing.", **U)
declare("V006", "dimension-not-positive", ERROR, "A box size, radius or length that is zero or negative.")
declare("V007", "rgba-out-of-range", ERROR, "An rgba component outside [0, 1].", **U)

# Geometry and materials
declare("G001", "geometry-empty", ERROR, "`<geometry>` holds no shape.", **U)
declare("G002", "geometry-unknown-shape", ERROR, "`<geometry>` holds an unknown shape.", **U)
declare("G003", "geometry-multiple-shapes", WARNING, "`<geometry>` holds more than one shape; only the first is used.")
declare("M001", "material-without-color", ERROR, "A top-level material with neither colour nor texture.", **U)
declare("M002", "material-undefined", WARNING, "A visual names a material defined nowhere.")
declare("M003", "material-redefined", WARNING, "One material name is given different colours.")
declare("M004", "rgba-length", WARNING, "An rgba value without exactly four components.")

# Joints
declare("J001", "joint-type-missing", ERROR, "A `<joint>` has no `type`.", **U)
declare("J002", "joint-type-unknown", ERROR, "A joint type other than the six URDF types.", **U)
declare("J003", "joint-limit-missing", ERROR, "A revolute or prismatic joint without `<limit>`.", **U)
declare("J004", "joint-link-unspecified", ERROR, "A joint without `<parent link>` or `<child link>`.", **U)
declare("J005", "joint-link-not-found", ERROR, "A joint names a parent or child link that does not exist.", **U)
declare("J006", "joint-dynamics-empty", ERROR, "`<dynamics>` with neither damping nor friction.", **U)

# Tree
declare("T001", "multiple-roots", ERROR, "More than one link has no parent.", **U)
declare("T002", "no-root", ERROR, "Every link has a parent: there is no root.", **U)
declare("T003", "multiple-parents", ERROR, "A link is the child of more than one joint.")
declare("T004", "kinematic-loop", ERROR, "The joints form a loop.")
