#include <softchain/chain/chain_contact.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace softchain::chain
{
  void ChainContact::set(const CollisionSurface *surface, const double pressure,
                         const std::vector<data::ObstacleRecord> &obstacles, const double stiffness,
                         const std::vector<double> &skin_compliance, const double shear_compliance,
                         const double path, std::vector<StickAnchor> anchors)
  {
    obstacles_.clear();
    poses_.clear();
    touches_.clear();
    skin_compliance_.clear();
    surface_   = surface;
    stiffness_ = stiffness;
    friction_.set({}, stiffness, 0.0, {});
    if (obstacles.empty())
      return;
    if (surface == nullptr)
      throw std::invalid_argument("chain contact: the model has no collision surface for obstacle '" +
                                  obstacles.front().name + "'");
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
      throw std::invalid_argument("chain contact: the contact stiffness must be positive and finite");
    std::vector<double> coefficients;
    for (const data::ObstacleRecord &record : obstacles)
      {
        obstacles_.emplace_back(record);
        poses_.push_back(obstacles_.back().pose(path));
        coefficients.push_back(record.friction);
      }
    friction_.set(coefficients, stiffness, shear_compliance, std::move(anchors));
    surface->offsets_at(pressure, offsets_);
    spheres_ = &surface->spheres_at(pressure);
    for (const double c : skin_compliance)
      if (!(c >= 0.0) || !std::isfinite(c))
        throw std::invalid_argument("chain contact: a skin compliance is negative or not finite");
    if (std::any_of(skin_compliance.begin(), skin_compliance.end(), [](double c) { return c > 0.0; }))
      {
        if (skin_compliance.size() + 1 != surface->link_begin().size())
          throw std::invalid_argument("chain contact: one skin compliance per link is needed");
        skin_compliance_ = skin_compliance;
        skin_shift_.assign(skin_compliance.size(), 0.0);
      }
  }

  // The touches are the points inside an obstacle: g < 0. With a skin, each
  // link's points near the obstacles (at s = 0) are displaced by its s_b
  // first. "Near": a skin that relieves its touching points (a_k > 0) gives
  // at most their deepest penetration over a_k (then none would push), so
  // the points within that of an obstacle are all that may touch at s_b.
  double ChainContact::update(const ChainPose &pose)
  {
    double energy = 0.0;
    if (!has_skin())
      candidates(pose, 0.0, touches_);
    else
      {
        std::fill(skin_shift_.begin(), skin_shift_.end(), 0.0);
        std::vector<Touch> &near = near_at_rest_; // their gaps and normals (their curvature: touch_inside below)
        candidates(pose, 0.0, near, false);
        double reach = 0.0;
        for (const Touch &t : near)
          {
            const double a = gives(t) ? t.normal.dot(skin_direction(pose, t.link)) : 0.0;
            if (a > 0.0)
              reach = std::max(reach, -t.gap / a);
          }
        if (reach > 0.0)
          candidates(pose, reach, near, false);
        touches_.clear();
        for (auto first = near.begin(); first != near.end();)
          {
            const int  link = first->link;
            const auto last = std::find_if(first, near.end(), [&](const Touch &t) { return t.link != link; });
            const Points group{&*first, static_cast<std::size_t>(last - first)};
            const double s = skin_compliance_[link] > 0.0 ? skin_shift(link, group) : 0.0;
            skin_shift_[link] = s;
            energy += skin_compliance_[link] > 0.0 ? 0.5 * s * s / skin_compliance_[link] : 0.0;
            const Eigen::Vector3d shift = s * skin_direction(pose, link);
            for (const Touch &point : group)
              {
                Touch      touch;
                const bool moves = gives(point);
                if (touch_inside(point, moves ? s : 0.0, moves ? shift : Eigen::Vector3d::Zero(), touch))
                  touches_.push_back(touch);
              }
            first = last;
          }
      }
    for (const Touch &touch : touches_)
      energy += 0.5 * stiffness_ * touch.gap * touch.gap;
    if (friction_.any())
      energy += friction_.update(pose, offsets_);
    return energy;
  }

  Eigen::Vector3d ChainContact::skin_direction(const ChainPose &pose, const int link) const
  {
    return pose.link_rotations[link].col(1);
  }

  bool ChainContact::gives(const Touch &touch) const
  {
    return has_skin() && skin_compliance_[touch.link] > 0.0 && surface_->gives(touch.point);
  }

  bool ChainContact::touch_at(const Eigen::Vector3d &x, const int link, const int k, const int o,
                              Touch &touch) const
  {
    const geometry::SignedDistance d = obstacles_[o].body->distance(x, poses_[o]);
    touch = {link, k, o, x, d.normal, Eigen::Vector3d(-stiffness_ * std::min(d.gap, 0.0) * d.normal),
             d.gap, d.hessian};
    return d.gap < 0.0;
  }

  // The gap alone first, seen from the link: most points tested lie
  // outside, and the distance's normal and curvature cost several times as much.
  bool ChainContact::touch_inside(const Touch &point, const double s, const Eigen::Vector3d &shift,
                                  Touch &touch) const
  {
    const Eigen::Vector3d L = offsets_[point.point] + Eigen::Vector3d(0.0, s, 0.0);
    return framed(point.link, point.obstacle).closer_than(L, 0.0) &&
           touch_at(point.position + shift, point.link, point.point, point.obstacle, touch);
  }

  // E'(s) = k_s s + sum_k k_c min(g_k(s), 0) a_k(s) is increasing where the
  // points' normals lie along d (a_k >= 0, plane and round obstacles alike
  // to first order), so the root is bracketed from s = 0 towards -E'(0) and
  // found by Newton's method, bisecting where a step leaves the bracket.
  double ChainContact::skin_shift(const int link, const Points near) const
  {
    const double k_s = 1.0 / skin_compliance_[link];
    double       scale = 0.0;
    // In the link's frame (the pose's, frame_obstacles): the point at
    // L_k + s e_y, d = e_y, a = n . e_y.
    const Eigen::Vector3d e_y = Eigen::Vector3d::UnitY();
    const auto            slope = [&](const double s, double &curvature) {
      double value = k_s * s;
      curvature    = k_s;
      scale        = std::abs(value);
      for (const Touch &point : near)
        {
          if (!gives(point))
            continue;
          const geometry::ObstacleInFrame &seen = framed(link, point.obstacle);
          const Eigen::Vector3d            L    = offsets_[point.point] + s * e_y;
          if (!seen.closer_than(L, 0.0))
            continue;
          Eigen::Vector3d n;
          double          bending = 0.0;
          const double    g       = seen.gap_normal_and_curvature(L, e_y, n, bending);
          const double    a       = n.y();
          value += stiffness_ * g * a;
          scale += std::abs(stiffness_ * g * a);
          curvature += stiffness_ * (a * a + g * bending);
        }
      return value;
    };
    double       curvature = 0.0;
    const double start     = slope(0.0, curvature);
    if (start == 0.0)
      return 0.0;
    const double sign = start < 0.0 ? 1.0 : -1.0; // the root lies at sign * |s|
    double       inner = 0.0, outer = -start / k_s, unused = 0.0;
    for (int i = 0; i < 60 && sign * slope(outer, unused) < 0.0; ++i)
      outer *= 2.0;
    double s = inner - start / curvature;
    for (int iteration = 0; iteration < 100; ++iteration)
      {
        if (!(sign * (s - inner) > 0.0 && sign * (outer - s) > 0.0))
          s = 0.5 * (inner + outer);
        const double value = slope(s, curvature);
        if (std::abs(value) <= 1e-14 * scale || std::abs(outer - inner) <= 1e-15 * std::abs(s))
          break;
        (sign * value < 0.0 ? inner : outer) = s;
        s -= value / curvature;
      }
    return s;
  }

  void ChainContact::skins(const ChainPose &pose, std::vector<Skin> &skins) const
  {
    skins.clear();
    for (std::size_t b = 0; b < skin_compliance_.size(); ++b)
      if (skin_compliance_[b] > 0.0)
        {
          Skin skin;
          skin.link      = static_cast<int>(b);
          skin.direction = skin_direction(pose, skin.link);
          skin.shift     = skin_shift_[b];
          skin.stiffness = 1.0 / skin_compliance_[b];
          skins.push_back(skin);
        }
    auto skin = skins.begin();
    for (const Touch &touch : touches_)
      {
        while (skin != skins.end() && skin->link < touch.link)
          ++skin;
        if (skin == skins.end() || skin->link != touch.link || !gives(touch))
          continue;
        const Eigen::Vector3d &d = skin->direction;
        const double           f = stiffness_ * touch.gap;
        skin->penetration_row += f * LinkWrenchStiffness::point_row(touch.position, touch.curvature * d);
        // d turns with the link: d(n . d)/dq_{i,alpha} = a_{i,alpha} . (d x n),
        // the row of a turn alone (w_b . (d x n)).
        skin->penetration_row.head<3>() += f * d.cross(touch.normal);
        skin->penetration_curvature += f * d.dot(touch.curvature * d);
      }
  }

  void ChainContact::friction_rows(std::vector<LinkRow> &rows) const
  {
    rows.clear();
    for (const CoulombFriction::Grip &grip : friction_.grips())
      for (int r = 0; r < 2; ++r)
        if (grip.rows[r].second > 0.0)
          rows.push_back({grip.link, LinkWrenchStiffness::point_row(grip.position, grip.rows[r].first),
                          grip.rows[r].second});
  }

  // A point new in contact sticks where it entered the obstacle, on the
  // line from its start x_s (gap g_s > 0) to its point x (gap g < 0) at
  // the zero of the linearly interpolated gap, x_s + g_s / (g_s - g) (x - x_s).
  std::vector<StickAnchor> ChainContact::touching_anchors(const ChainPose &pose, const std::vector<StickAnchor> &held,
                                                          const std::vector<Eigen::Vector3d> &start) const
  {
    std::vector<StickAnchor> anchors;
    for (const Touch &touch : touches_)
      {
        if (!(friction_.coefficient(touch.obstacle) > 0.0))
          continue;
        const auto same = std::find_if(held.begin(), held.end(), [&](const StickAnchor &a) {
          return a.point == touch.point && a.obstacle == touch.obstacle;
        });
        Eigen::Vector3d anchor = start[touch.point];
        if (same != held.end())
          anchor = same->position;
        else
          {
            const geometry::Obstacle &obstacle = obstacles_[touch.obstacle];
            const Eigen::Vector3d     x =
              pose.link_origins[touch.link] + pose.link_rotations[touch.link] * offsets_[touch.point];
            const double before = obstacle.body->gap(anchor, poses_[touch.obstacle]);
            const double now    = obstacle.body->gap(x, poses_[touch.obstacle]);
            if (before > 0.0 && now < 0.0)
              anchor += before / (before - now) * (x - anchor);
          }
        anchors.push_back({touch.link, touch.point, touch.obstacle, anchor, touch.normal, touch.force.norm()});
      }
    return anchors;
  }

  void ChainContact::surface_positions(const ChainPose &pose, std::vector<Eigen::Vector3d> &positions) const
  {
    const std::vector<int> &links = surface_->links();
    positions.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k)
      positions[k] = pose.link_origins[links[k]] + pose.link_rotations[links[k]] * offsets_[k];
  }

  // The normal row (weight k_c) if `normal`, and each eigenvector e of H_g
  // with eigenvalue mu != 0 (a round obstacle's 1/radius) with weight
  // k_c g mu.
  void ChainContact::append_rows(const Touch &touch, const bool normal, std::vector<LinkRow> &rows) const
  {
    if (normal)
      rows.push_back({touch.link, LinkWrenchStiffness::point_row(touch.position, touch.normal), stiffness_});
    if (touch.curvature.isZero())
      return;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(touch.curvature);
    const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      if (std::abs(eigen.eigenvalues()[i]) > 1e-9 * largest)
        rows.push_back({touch.link, LinkWrenchStiffness::point_row(touch.position, eigen.eigenvectors().col(i)),
                        stiffness_ * touch.gap * eigen.eigenvalues()[i]});
  }

  // With a skin, one row u_b per touching link with weight -1 / D_b (header).
  void ChainContact::tangent_rows(const ChainPose &pose, std::vector<LinkRow> &rows) const
  {
    rows.clear();
    for (const Touch &touch : touches_)
      append_rows(touch, true, rows);
    std::vector<LinkRow> friction;
    friction_rows(friction);
    rows.insert(rows.end(), friction.begin(), friction.end());
    if (!has_skin())
      return;
    std::vector<Skin> links;
    skins(pose, links);
    for (const Skin &skin : links)
      {
        LinkWrenchStiffness::Vector6d u = skin.penetration_row;
        double                        D = skin.stiffness + skin.penetration_curvature;
        bool                          touching = false;
        for (const Touch &touch : touches_)
          if (touch.link == skin.link && gives(touch))
            {
              const double a = touch.normal.dot(skin.direction);
              u += stiffness_ * a * LinkWrenchStiffness::point_row(touch.position, touch.normal);
              D += stiffness_ * a * a;
              touching = true;
            }
        if (touching)
          rows.push_back({skin.link, u, -1.0 / D});
      }
  }

  void ChainContact::curvature_rows(std::vector<LinkRow> &rows) const
  {
    rows.clear();
    for (const Touch &touch : touches_)
      append_rows(touch, false, rows);
  }

  // Down each link's tree of spheres (CollisionSurface::nodes), so that
  // the points come sorted by link; a node whose sphere lies farther than
  // `margin` from every obstacle (clearance > margin, g being 1-Lipschitz)
  // has no point within it, and in a cluster only the obstacles its sphere
  // reaches are tested. A point inside (g < 0) carries f = -k_c g n.
  // (CollisionSurface::walk's loop, written out: the hottest of the walks,
  // it measured 7 % slower through walk's closures on P10's contact samples.)
  void ChainContact::candidates(const ChainPose &pose, const double margin, std::vector<Touch> &near,
                                const bool with_curvature) const
  {
    near.clear();
    if (obstacles_.empty())
      return;
    frame_obstacles(pose);
    const std::vector<CollisionSurface::Node> &nodes = surface_->nodes();
    for (std::size_t i = 0; i < nodes.size();)
      {
        const CollisionSurface::Node &node = nodes[i];
        if (clearance(static_cast<int>(i)) > margin)
          i = node.skip;
        else if (node.cluster < 0)
          ++i;
        else
          {
            add_candidates(pose, surface_->clusters()[node.cluster], (*spheres_)[i], margin, with_curvature, near);
            i = node.skip;
          }
      }
  }

  void ChainContact::add_candidates(const ChainPose &pose, const CollisionSurface::Cluster &cluster,
                                    const CollisionSurface::Sphere &sphere, const double margin,
                                    const bool with_curvature, std::vector<Touch> &near) const
  {
    const Eigen::Matrix3d &R      = pose.link_rotations[cluster.link];
    const Eigen::Vector3d &c      = pose.link_origins[cluster.link];
    const double           s      = has_skin() ? skin_shift_[cluster.link] : 0.0;
    const Eigen::Vector3d  skin(0.0, s, 0.0);
    for (std::size_t o = 0; o < obstacles_.size(); ++o)
      {
        const geometry::ObstacleInFrame &seen = framed(cluster.link, static_cast<int>(o));
        if (seen.gap(sphere.centre) > sphere.radius + std::abs(s) + margin)
          continue;
        for (int k = cluster.begin; k < cluster.end; ++k)
          {
            if (seen.is_plane() && surface_->between_vertices(k))
              continue; // never deeper than its vertices (CollisionSurface)
            const Eigen::Vector3d L = surface_->gives(k) ? Eigen::Vector3d(offsets_[k] + skin) : offsets_[k];
            if (!seen.closer_than(L, margin))
              continue;
            const Eigen::Vector3d x = c + R * L;
            if (with_curvature)
              {
                near.emplace_back();
                touch_at(x, cluster.link, k, static_cast<int>(o), near.back());
                continue;
              }
            Eigen::Vector3d n;
            const double    g = seen.gap_and_normal(L, n);
            n                 = R * n;
            near.push_back({cluster.link, k, static_cast<int>(o), x, n,
                            Eigen::Vector3d(-stiffness_ * std::min(g, 0.0) * n), g, Eigen::Matrix3d::Zero()});
          }
      }
  }

  double ChainContact::clearance(const int node) const
  {
    return clearance_at_rest(node) - skin_reach(surface_->nodes()[node].link);
  }

  void ChainContact::frame_obstacles(const ChainPose &pose) const
  {
    const std::size_t n_links = pose.link_rotations.size();
    framed_.resize(n_links * obstacles_.size());
    for (std::size_t b = 0; b < n_links; ++b)
      for (std::size_t o = 0; o < obstacles_.size(); ++o)
        framed_[b * obstacles_.size() + o] =
          obstacles_[o].body->seen_from(pose.link_rotations[b], pose.link_origins[b], poses_[o]);
  }

  double ChainContact::clearance_at_rest(const int node) const
  {
    const int                       link   = surface_->nodes()[node].link;
    const CollisionSurface::Sphere &sphere = (*spheres_)[node];
    double                          nearest = std::numeric_limits<double>::infinity();
    for (std::size_t o = 0; o < obstacles_.size(); ++o)
      nearest = std::min(nearest, framed(link, static_cast<int>(o)).gap(sphere.centre));
    return nearest - sphere.radius;
  }

  double ChainContact::skin_reach(const int link) const
  {
    return has_skin() ? std::abs(skin_shift_[link]) : 0.0;
  }

  // With the skins at rest (s_b = 0). A point inside then is still inside
  // once the skins have given: a skin gives only as far as the force of its
  // points that still push holds it (ChainContact::skin_shift).
  bool ChainContact::penetrates(const ChainPose &pose) const
  {
    if (obstacles_.empty())
      return false;
    frame_obstacles(pose);
    return surface_->walk([&](const int node) { return clearance_at_rest(node) > 0.0; },
                          [&](const int n) {
                            const CollisionSurface::Node &node = surface_->nodes()[n];
                            for (int k = node.begin; k < node.end; ++k)
                              for (std::size_t o = 0; o < obstacles_.size(); ++o)
                                if (framed(node.link, static_cast<int>(o)).closer_than(offsets_[k], 0.0))
                                  return true;
                            return false;
                          });
  }

  std::vector<data::ObstacleWrench> ChainContact::obstacle_wrenches() const
  {
    std::vector<Eigen::Vector3d> force(obstacles_.size(), Eigen::Vector3d::Zero()),
      moment(obstacles_.size(), Eigen::Vector3d::Zero());
    for (const Touch &touch : touches_)
      {
        force[touch.obstacle] -= touch.force;
        moment[touch.obstacle] -= touch.position.cross(touch.force);
      }
    for (const CoulombFriction::Grip &grip : friction_.grips())
      {
        force[grip.obstacle] -= grip.force;
        moment[grip.obstacle] -= grip.position.cross(grip.force);
      }
    std::vector<data::ObstacleWrench> wrenches(obstacles_.size());
    for (std::size_t o = 0; o < obstacles_.size(); ++o)
      for (int i = 0; i < 3; ++i)
        {
          wrenches[o].force[i]  = force[o][i];
          wrenches[o].moment[i] = moment[o][i];
        }
    return wrenches;
  }

  double ChainContact::max_penetration() const
  {
    double deepest = 0.0;
    for (const Touch &touch : touches_)
      deepest = std::max(deepest, -touch.gap);
    return deepest;
  }
} // namespace softchain::chain
