// The KDL tree robot_state_publisher builds from a URDF file, printed as one JSON line:
// urdfdom reads the file, kdl_parser's treeFromUrdfModel makes the tree (its warnings go
// to standard error). tests/test_targets.py compiles this with the system compiler:
//   g++ -std=c++17 kdl_tree.cpp -o kdl_tree -lkdl_parser -lorocos-kdl -lurdfdom_model
#include <cmath>
#include <cstdio>
#include <string>

#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>
#include <urdf_parser/urdf_parser.h>

static void number(double value) {
  if (std::isfinite(value)) std::printf("%.17g", value);
  else std::printf("null");  // a zero axis becomes NaN
}

static void numbers(const double* values, int count) {
  for (int i = 0; i < count; ++i) {
    std::printf(i ? ", " : "[");
    number(values[i]);
  }
  std::printf("]");
}

static int refused(const char* why) {
  std::printf("{\"accepted\": false, \"error\": \"%s\"}\n", why);
  return 0;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: kdl_tree FILE.urdf\n");
    return 2;
  }
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(argv[1]);
  if (!model) return refused("urdfdom could not read the model");
  KDL::Tree tree;
  if (!kdl_parser::treeFromUrdfModel(*model, tree)) return refused("treeFromUrdfModel failed");
  const std::string root = tree.getRootSegment()->first;
  std::printf("{\"accepted\": true, \"root\": \"%s\", \"segments\": [", root.c_str());
  bool first = true;
  for (const auto& entry : tree.getSegments()) {
    if (entry.first == root) continue;  // the base: no joint, no inertia
    const KDL::Segment& segment = GetTreeElementSegment(entry.second);
    const KDL::Joint& joint = segment.getJoint();
    const KDL::RigidBodyInertia& inertia = segment.getInertia();
    const KDL::Vector axis = joint.JointAxis(), cog = inertia.getCOG();
    std::printf("%s{\"name\": \"%s\", \"joint\": \"%s\", \"type\": \"%s\", \"axis\": ", first ? "" : ", ",
                entry.first.c_str(), joint.getName().c_str(), joint.getTypeName().c_str());
    numbers(axis.data, 3);
    std::printf(", \"mass\": ");
    number(inertia.getMass());
    std::printf(", \"cog\": ");
    numbers(cog.data, 3);
    std::printf(", \"inertia\": ");  // about the segment's origin, in its axes
    numbers(inertia.getRotationalInertia().data, 9);
    std::printf("}");
    first = false;
  }
  std::printf("]}\n");
  return 0;
}
