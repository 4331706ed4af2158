// Joints on the strain-limiting layer (JointGeometry, BodySamples,
// NeutralLayer) on structured box meshes of tetrahedra and hexahedra under
// closed-form deformations: an affine map, a finger hinged at its joints on
// the layer, bending onto an arc about the layer, a uniform stretch.
#include <softchain/data/input_error.h>
#include <softchain/data/joint_angles.h>
#include <softchain/data/vector_of_point.h>
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/neutral_layer.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "../chain/box_mesh.h"
#include "layer_finger_mesh.h"

using namespace softchain;
using namespace softchain::reduction;
using softchain::chain::testing::box_mesh;
using softchain::chain::testing::BoxMeshSpec;

namespace
{
  constexpr double mm = 1e-3;
  constexpr double a  = 10 * mm;
  // Coordinates are <= 0.1 m and every map is evaluated in a few flops, so
  // positions agree to ~1e-17 m; angles from SVDs of slabs >= 3 mm wide to
  // ~1e-14 rad. "Exact" below leaves a margin of 100 over both.
  constexpr double exact_position = 1e-15; // m
  constexpr double exact_angle    = 1e-12; // rad

  const std::vector<RotationMethod> both_methods = {RotationMethod::bounding_box,
                                                    RotationMethod::affine_fit};

  data::MeshRecord finger_mesh(bool tetrahedra)
  {
    return testing::layer_finger_mesh(tetrahedra);
  }

  std::vector<data::Point3> deform(const std::vector<data::Point3> &X,
                                   const std::function<Eigen::Vector3d(const Eigen::Vector3d &)> &map)
  {
    std::vector<data::Point3> x;
    for (const auto &p : X)
      {
        const Eigen::Vector3d y = map(data::vector_of(p));
        x.push_back({y(0), y(1), y(2)});
      }
    return x;
  }

  // A chain of rigid links through the joints J_k,0 with relative rotations
  // E_k (R_0 = I): c_1 = J_1,0, c_k+1 = c_k + R_k (J_k+1,0 - J_k,0),
  // tip = c_n + R_n (T - J_n,0). Returns the joint positions, then the tip.
  std::vector<Eigen::Vector3d> chain_positions(const JointGeometry &geometry,
                                               const std::vector<Eigen::Matrix3d> &relative,
                                               const Eigen::Vector3d &tip)
  {
    std::vector<Eigen::Vector3d> c = {geometry.reference_centre(0)};
    Eigen::Matrix3d              R = Eigen::Matrix3d::Identity();
    for (std::size_t k = 0; k < relative.size(); ++k)
      {
        R                         = R * relative[k];
        const Eigen::Vector3d next = k + 1 < relative.size() ? geometry.reference_centre(k + 1) : tip;
        c.push_back(c.back() + R * (next - geometry.reference_centre(k)));
      }
    return c;
  }

  // The finger hinged at its joints on the layer y = 0: segment 0 is the
  // base up to x_1, segment k = 1..n the material of link k, moved rigidly by
  // the chain of relative rotations E_k about the joints:
  //   X -> c_k + R_k (X - J_k,0),  R_k = E_1 ... E_k.
  struct Hinged
  {
    std::vector<Eigen::Matrix3d> relative;
    std::vector<Eigen::Vector3d> joints; // J_k,0 on the layer

    Eigen::Vector3d operator()(const Eigen::Vector3d &X, std::size_t segment) const
    {
      Eigen::Vector3d c = joints[0];
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
      for (std::size_t k = 1; k <= segment; ++k)
        {
          if (k > 1)
            c += R * (joints[k - 1] - joints[k - 2]);
          R = R * relative[k - 1];
        }
      return segment == 0 ? X : Eigen::Vector3d(c + R * (X - joints[segment - 1]));
    }
  };

  Hinged hinged(int n_joints)
  {
    Hinged h;
    for (int k = 0; k < n_joints; ++k)
      {
        h.joints.emplace_back((k + 0.5) * a, 0.0, 0.0);
        h.relative.push_back(data::rotation_from_angles({0.02 * k, -0.05 + 0.01 * k, -0.15 - 0.02 * k}));
      }
    return h;
  }

  // The finger of finger_mesh() cut at the joint planes into separate
  // meshes of its segments (nodes on a cut belong to both sides), so that
  // each segment can move rigidly; the segment of every node.
  struct SegmentedMesh
  {
    data::MeshRecord         mesh;
    std::vector<std::size_t> segment;
  };

  SegmentedMesh segmented_mesh(bool tetrahedra)
  {
    SegmentedMesh result;
    const std::vector<double> cuts = {0, 5, 15, 25, 35, 45, 55, 65, 75, 85, 90};
    for (std::size_t s = 0; s + 1 < cuts.size(); ++s)
      {
        BoxMeshSpec spec;
        spec.length     = (cuts[s + 1] - cuts[s]) * mm;
        spec.nx         = int(std::lround((cuts[s + 1] - cuts[s]) / 5));
        spec.wall_cells = 1;
        spec.tetrahedra = tetrahedra;
        const data::MeshRecord part   = box_mesh(spec);
        const std::int64_t     offset = std::int64_t(result.mesh.X.size());
        for (const auto &X : part.X)
          {
            result.mesh.X.push_back({X[0] + cuts[s] * mm, X[1], X[2]});
            result.segment.push_back(s);
          }
        for (const auto node : part.cells)
          result.mesh.cells.push_back(node + offset);
        result.mesh.nodes_per_cell = part.nodes_per_cell;
      }
    return result;
  }

  data::SampleRecord sample_of(const std::vector<data::Point3> &x, double pressure)
  {
    data::SampleRecord s;
    s.id                 = "closed-form";
    s.actuation.role     = "pressure";
    s.actuation.pressure = pressure;
    s.x                  = x;
    return s;
  }
} // namespace

TEST_CASE("the body lattice samples the volume and moves exactly with an affine field")
{
  for (const bool tetrahedra : {true, false})
    {
      const data::MeshRecord mesh = finger_mesh(tetrahedra);
      const BodySamples      body(mesh, 1 * mm, "box");
      // Walls and faces lie on multiples of 1 mm from the box corner and the
      // lattice at half-integers: the count is the body's volume in mm^3,
      // 90 x (12 x 16 - 8 x 12) = 8640, with no point on a face.
      CHECK(body.lattice().size() == 8640);
      CHECK_FALSE(body.locate({45 * mm, 4 * mm, 0}));  // in the cavity
      CHECK_FALSE(body.locate({45 * mm, 11 * mm, 0})); // above the body
      CHECK(body.locate({45 * mm, -1 * mm, 0}));

      Eigen::Matrix3d F;
      F << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.3;
      const Eigen::Vector3d c(0.01, -0.02, 0.03);
      const auto affine = [&](const Eigen::Vector3d &X) -> Eigen::Vector3d { return F * X + c; };
      const auto moved  = body.deformed_lattice(deform(mesh.X, affine));
      double     error  = 0;
      for (std::size_t q = 0; q < moved.size(); ++q)
        error = std::max(error, (data::vector_of(moved[q]) - affine(data::vector_of(body.lattice()[q]))).norm());
      CHECK(error < exact_position * 10); // the hexahedra's Newton inverse adds ~1e-16 m
    }
}

TEST_CASE("in a hexahedron that is not a parallelepiped a located point's weights reproduce it")
{
  // One hexahedron with every corner moved off the unit cube's (a trilinear,
  // not affine, map X(xi)): the Newton inverse must give weights N(xi) with
  // sum_a N_a X_a = X, for points all over the cell, and find nothing
  // outside it.
  data::MeshRecord mesh;
  const double     shift[8][3] = {{0, 0, 0},       {0.2, -0.1, 0.1}, {-0.1, 0.15, 0},  {0.1, 0.2, -0.15},
                                  {0.1, -0.1, 0.2}, {0.25, 0, 0.3},   {-0.15, 0.1, 0.2}, {0.3, 0.3, 0.25}};
  for (int k = 0; k < 8; ++k)
    mesh.X.push_back({(k & 1) + shift[k][0], ((k >> 1) & 1) + shift[k][1], ((k >> 2) & 1) + shift[k][2]});
  mesh.nodes_per_cell = 8;
  for (int k = 0; k < 8; ++k)
    mesh.cells.push_back(k);
  const BodySamples body(mesh, 0.05, "distorted hexahedron");
  REQUIRE(body.lattice().size() > 1000);
  double worst = 0;
  for (const auto &P : body.lattice())
    {
      const auto located = body.locate(data::vector_of(P));
      REQUIRE(located);
      // Interpolating the reference corners gives the point back.
      worst = std::max(worst, (body.deformed(*located, mesh.X) - data::vector_of(P)).norm());
    }
  CHECK(worst < 1e-12); // Newton stops at 1e-13 of the cell's size
  CHECK_FALSE(body.locate({2.0, 0.5, 0.5}));
  CHECK_FALSE(body.locate({0.5, -0.5, 0.5}));
}

TEST_CASE("a finger hinged at its joints on the layer is reduced exactly by M1 and M2")
{
  for (const bool tetrahedra : {true, false})
    {
      const SegmentedMesh segmented = segmented_mesh(tetrahedra);
      const auto         &mesh      = segmented.mesh;
      const JointLayout   layout(mesh.X, a, 0, "box");
      REQUIRE(layout.n_joints() == 9);
      const auto   body   = std::make_shared<const BodySamples>(mesh, a / 8, "box");
      const Hinged motion = hinged(layout.n_joints());
      std::vector<data::Point3> x;
      for (std::size_t j = 0; j < mesh.X.size(); ++j)
        {
          const Eigen::Vector3d y = motion(data::vector_of(mesh.X[j]), segmented.segment[j]);
          x.push_back({y(0), y(1), y(2)});
        }
      for (const double b : {a / 2, a / 3})
        for (const auto method : both_methods)
          {
            const JointGeometry geometry(layout, body, 0.0, b);
            const JointFrames   frames(method, geometry.slabs(), geometry.reference_points(),
                                       geometry.points(x), "hinged");
            std::vector<Eigen::Matrix3d> relative;
            for (std::size_t k = 0; k < frames.size(); ++k)
              {
                relative.push_back(data::rotation_from_angles(frames.relative_angles(k)));
                CHECK((relative.back() - motion.relative[k]).norm() < exact_angle);
                CHECK((geometry.deformed_centre(k, frames, x) -
                       motion(geometry.reference_centre(k), k + 1))
                        .norm() < exact_position * 100);
              }
            const Eigen::Vector3d tip(90 * mm, 0, 0);
            CHECK((chain_positions(geometry, relative, tip).back() - motion(tip, 9)).norm() <
                  exact_position * 100);
          }
    }
}

TEST_CASE("pure bending about a layer: its height is measured and the chain lands on the tip")
{
  // Bending onto an arc of radius R about z, distal to the first joint (the
  // base up to x_1 stays): the section at X > x_1 turns by -(X - x_1) / R
  // about the centre (x_1, y_f - R, 0), so that the fibre y = y_f = -1 mm
  // in the 2 mm bottom wall keeps its length.
  const double R      = 0.05;
  const double x1     = a / 2;
  const double y_f    = -1 * mm;
  const auto   arc    = [&](const Eigen::Vector3d &X) -> Eigen::Vector3d {
    if (X.x() <= x1)
      return X;
    const double angle = (X.x() - x1) / R, r = R + X.y() - y_f;
    return {x1 + r * std::sin(angle), y_f - R + r * std::cos(angle), X.z()};
  };
  for (const bool tetrahedra : {true, false})
    {
      const data::MeshRecord   mesh = finger_mesh(tetrahedra);
      const JointLayout        layout(mesh.X, a, 0, "box");
      const auto               body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
      const data::SampleRecord bent = sample_of(deform(mesh.X, arc), 1e4);
      const NeutralLayer       layer(body, layout, mesh, {&bent});
      REQUIRE(layer.measured());
      // A rigid link of length a matches the chord 2 (R + y) sin(a / 2R) of
      // the fibre at height y where y - y_f = a / (2 sin(a / 2R)) - R ~ a^2 / 24R
      // (0.083 mm). The joints lie on node planes, where the arc is affine in
      // (y, z): the chords are exact, and a chain through joints at that
      // height lands on every joint. The last link, a/2 long, carries the tip
      // face's centroid (4 mm higher) with its slab's rotation, (a/4) / R
      // behind the tip face's: E's tip term moves y_n by 0.027 mm (measured
      // on both meshes); 0.05 mm bounds it.
      const double best = y_f + a / (2 * std::sin(a / (2 * R))) - R;
      INFO("y_n = " << layer.height() << " m, closed form for the joints " << best << " m");
      CHECK(layer.height() == Approx(best).margin(0.05 * mm));
      const JointGeometry geometry(layout, body, layer.height(), a / 2);
      const JointFrames   frames(RotationMethod::affine_fit, geometry.slabs(),
                                 geometry.reference_points(), geometry.points(bent.x), "arc");
      std::vector<Eigen::Matrix3d> relative;
      for (std::size_t k = 0; k < frames.size(); ++k)
        relative.push_back(data::rotation_from_angles(frames.relative_angles(k)));
      const Eigen::Vector3d tip(90 * mm, layer.height(), 0);
      const double          miss = (chain_positions(geometry, relative, tip).back() - arc(tip)).norm();
      // On the neutral fibre each rigid link would be the chord of an arc of
      // its length l, short by l^3 / (24 R^2): 0.135 mm for 8 links of 10 mm
      // and one of 5 mm. At y_n the tip point on the layer is missed by
      // 36 um (measured on both meshes: the compromise with the tip face's
      // centroid above); a third of the chord shortfall bounds it.
      const double chords = (8 * std::pow(a, 3) + std::pow(a / 2, 3)) / (24 * R * R);
      CHECK(miss < chords / 3);
    }
}

TEST_CASE("a uniformly stretched finger: the stretch is recovered and no layer is measured")
{
  const double lambda = 1.07;
  for (const bool tetrahedra : {true, false})
    {
      const data::MeshRecord   mesh = finger_mesh(tetrahedra);
      const JointLayout        layout(mesh.X, a, 0, "box");
      // 1 mm: a lattice symmetric about the section's centre.
      const auto               body = std::make_shared<const BodySamples>(mesh, 1 * mm, "box");
      const data::SampleRecord stretched = sample_of(
        deform(mesh.X, [&](const Eigen::Vector3d &X) -> Eigen::Vector3d {
          return {lambda * X.x(), X.y(), X.z()};
        }),
        1e4);
      const NeutralLayer layer(body, layout, mesh, {&stretched});
      CHECK_FALSE(layer.measured());
      // The fallback: the hollow section's centroid (y from -2 to 10 mm, the
      // cavity's 8 mm x 12 mm centred at y = 4 mm like the outline) lies in
      // the cavity, so the joints go to the bottom wall's middle, y = -1 mm,
      // to the 64 probed heights (12 mm / 64 apart).
      CHECK(layer.height() == Approx(-1 * mm).margin(12 * mm / 64));
      const JointGeometry geometry(layout, body, 0.0, a / 3);
      const JointFrames   frames(RotationMethod::affine_fit, geometry.slabs(),
                                 geometry.reference_points(), geometry.points(stretched.x), "s");
      for (std::size_t k = 0; k < frames.size(); ++k)
        {
          CHECK(frames[k].stretches(0) == Approx(lambda).margin(1e-12));
          CHECK(frames[k].stretches(2) == Approx(1).margin(1e-12));
        }
    }
}

TEST_CASE("hexahedra with node planes 5.5 mm apart reduce at b = a/3 on the layer, not by nodes")
{
  BoxMeshSpec spec;
  spec.length     = 0.088;
  spec.nx         = 16; // 5.5 mm cells: nodes on planes 5.5 mm apart
  spec.wall_cells = 1;
  const data::MeshRecord mesh = box_mesh(spec);
  const JointLayout      layout(mesh.X, a, 0, "box");
  const Hinged           motion = hinged(layout.n_joints());
  const auto x = deform(mesh.X, [&](const Eigen::Vector3d &X) -> Eigen::Vector3d {
    return motion(X, std::size_t(layout.n_joints())); // a rigid motion: any sample will do
  });
  // By nodes, a slab 6.7 mm wide around x = 5 mm holds one node plane.
  CHECK_THROWS_WITH(JointFrames(RotationMethod::affine_fit, JointGeometry(layout, mesh, a / 3).slabs(),
                                mesh.X, x, "hex"),
                    Catch::Contains("one plane"));
  const auto          body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
  const JointGeometry geometry(layout, body, 0.0, a / 3);
  for (const auto method : both_methods)
    CHECK_NOTHROW(JointFrames(method, geometry.slabs(), geometry.reference_points(),
                              geometry.points(x), "hex"));
}

TEST_CASE("a joint height outside the body is an error naming the joint")
{
  const data::MeshRecord mesh = finger_mesh(true);
  const JointLayout      layout(mesh.X, a, 0, "box");
  const auto             body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
  CHECK_THROWS_WITH(JointGeometry(layout, body, 4 * mm, a / 2), // inside the cavity
                    Catch::Contains("joint 1") && Catch::Contains("outside the body"));
  data::MeshRecord no_cells = mesh;
  no_cells.cells.clear();
  CHECK_THROWS_AS(BodySamples(no_cells, a / 8, "box"), data::InputError);
}

TEST_CASE("without pressure samples the joints sit at the centroid, or in the bottom wall of a hollow finger")
{
  chain::testing::BoxMeshSpec spec; // y from -2 to 10 mm
  const data::MeshRecord      solid = chain::testing::box_mesh(spec);
  const JointLayout           layout(solid.X, a, 0, "box");
  const NeutralLayer at_centroid(std::make_shared<const BodySamples>(solid, a / 8, "box"), layout, solid, {});
  CHECK_FALSE(at_centroid.measured());
  // The lattice's mean: its points, h = 1.25 mm apart from the box's corner,
  // need not be centred in the box, by at most h / 2.
  CHECK(at_centroid.height() == Approx(4 * mm).margin(0.625 * mm));
  // Hollow, with 2 mm walls: the centroid lies in the cavity, where no joint
  // can be; the bottom wall's middle is y = -1 mm, to the 64 probed heights
  // (12 mm / 64 apart).
  const data::MeshRecord hollow = finger_mesh(true);
  const NeutralLayer in_wall(std::make_shared<const BodySamples>(hollow, a / 8, "box"), layout, hollow, {});
  CHECK_FALSE(in_wall.measured());
  CHECK(in_wall.height() == Approx(-1 * mm).margin(12 * mm / 64));
  CHECK_THAT(in_wall.description(), Catch::Contains("lowest solid layer"));
  CHECK_NOTHROW(JointGeometry(layout, std::make_shared<const BodySamples>(hollow, a / 8, "box"), in_wall.height(),
                              a / 2));
}

TEST_CASE("a joint spacing mistyped by orders of magnitude is an error at once, not a full memory")
{
  const data::MeshRecord mesh = finger_mesh(true);
  // 90 mm at 0.1 um would be 900,000 joints; at 1e-12 m more than an int holds.
  for (const double spacing : {1e-7, 1e-12})
    CHECK_THROWS_WITH(JointLayout(mesh.X, spacing, 0, "box"),
                      Catch::Contains("box: the mesh is 0.09 m long") &&
                        Catch::Contains("(Reduction/Joint spacing) gives") &&
                        Catch::Contains("joints, more than 1000"));
  CHECK(JointLayout(mesh.X, 0.09 / max_joints, 0, "box").n_joints() == max_joints);
  // Below that the body's lattice is the bound: at a = 0.5 mm (h = 62.5 um)
  // the 90 mm box holds more than 1e7 of its points, and the message says
  // which a fits.
  CHECK_THROWS_WITH(BodySamples(mesh, 0.5 * mm / lattice_points_per_spacing, "box"),
                    Catch::Contains("Reduction/Joint spacing a = 0.0005 m") &&
                      Catch::Contains("more than 1e+07") && Catch::Contains("at least"));
}
