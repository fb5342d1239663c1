#include "scene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "backdrop.h"
#include "gl_api.h"
#include "mesh.h"
#include "reach.h"

namespace afford::render {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

struct GlColour {
  float r, g, b, a = 1;
};
// The palette (before lighting).
constexpr GlColour kFixedArm{0.58f, 0.60f, 0.64f};
constexpr GlColour kMovingArm{0.33f, 0.48f, 0.72f};
constexpr GlColour kStressed{0.86f, 0.20f, 0.14f};
constexpr GlColour kThumb{0.92f, 0.45f, 0.35f};
constexpr GlColour kFinger{0.95f, 0.72f, 0.58f};
constexpr GlColour kHand{0.95f, 0.76f, 0.64f, 0.28f};
constexpr GlColour kObjectActeeContact{0.15f, 0.80f, 0.30f};
constexpr GlColour kAgentContact{0.10f, 0.65f, 0.95f};
constexpr GlColour kEffortArrow{0.98f, 0.62f, 0.05f};
constexpr GlColour kActeeArrow{0.85f, 0.10f, 0.10f};

// Knuckles in the hand frame (engine/session/script.h: +x to the fingers, +y to the
// thumb, the palm facing -z) and the palm box.
const Vector3d kKnuckle[kFingers] = {{0.025, 0.040, -0.015},
                                     {0.075, 0.025, -0.012},
                                     {0.078, 0.006, -0.012},
                                     {0.075, -0.013, -0.012},
                                     {0.068, -0.030, -0.012}};
const Vector3d kPalmCentre(0.040, -0.002, -0.004), kPalmSize(0.080, 0.080, 0.020);
constexpr double kFingerRadius = 0.0075;  // m

glm::mat4 projection_of(const Camera& c, double aspect, double near_m, double far_m) {
  return glm::perspective(static_cast<float>(c.fov), static_cast<float>(aspect), static_cast<float>(near_m),
                          static_cast<float>(far_m));
}

glm::vec3 vec(const Vector3d& v) { return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())}; }

glm::mat4 view_of(const Camera& c) { return glm::lookAt(vec(c.position), vec(c.target), vec(usable_up(c))); }

// Near and far planes around the target: generous, for the hand above the tool.
void clip_planes(const Camera& c, double* near_m, double* far_m) {
  const double d = (c.target - c.position).norm();
  *near_m = std::max(1e-3, d * 0.05);
  *far_m = d * 6 + 1;
}

void set_colour(const GlColour& c) { gl().Color4f(c.r, c.g, c.b, c.a); }

GlColour mix(const GlColour& a, const GlColour& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t};
}

void draw(const Mesh& m) {
  if (m.vertices() == 0) return;
  gl().VertexPointer(3, GL_FLOAT, 0, m.pos.data());
  gl().NormalPointer(GL_FLOAT, 0, m.nrm.data());
  gl().DrawArrays(GL_TRIANGLES, 0, m.vertices());
}

void push_pose(const Isometry3d& pose) {
  gl().PushMatrix();
  const Eigen::Matrix4f m = pose.matrix().cast<float>();
  gl().MultMatrixf(m.data());
}

GlColour colour_of(const ActeeLook::Srgb& c) { return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f}; }

// Scales by k along d (unit) and by `across` across it.
void squash_along(const Vector3d& d, double k, double across) {
  Eigen::Matrix4f squash = Eigen::Matrix4f::Identity();
  squash.topLeftCorner<3, 3>() =
      (across * Eigen::Matrix3d::Identity() + (k - across) * d * d.transpose()).cast<float>();
  gl().MultMatrixf(squash.data());
}

// Where a nut splits: across its longest axis of those across the force,
// so that the halves open sideways from the jaws.
int split_axis(const Eigen::AlignedBox3d& local, const Vector3d& d) {
  int best = 0;
  double best_len = -1;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) > 0.7) continue;  // along the force
    if (local.sizes()[a] > best_len + 1e-12) best = a, best_len = local.sizes()[a];
  }
  return best;
}

}  // namespace

Vector3d usable_up(const Camera& c) {
  const Vector3d view = (c.target - c.position).normalized();
  if (c.up.cross(view).norm() > 1e-6) return c.up;
  return std::abs(view.z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitY();
}

Rgb actee_base_colour() {
  const ActeeLook::Srgb c = ActeeLook{}.colour;
  return {c[0], c[1], c[2]};
}

Rgb actee_colour(const Model& m) { return {m.actee_look.colour[0], m.actee_look.colour[1], m.actee_look.colour[2]}; }

Eigen::AlignedBox3d scene_box(const Model& m, const State& s) {
  Eigen::AlignedBox3d box;
  const Isometry3d moving = s.object_pose * moving_arm_pose(s.theta);
  auto add = [&box](const Geometry& g, const Isometry3d& pose) {
    const Eigen::AlignedBox3d& b = g.local_box();
    for (int i = 0; i < 8; ++i) box.extend(pose * b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)));
  };
  for (const ModelPart& p : m.parts) add(p.geometry, (p.arm == Arm::moving ? moving : s.object_pose) * p.in_arm);
  if (m.has_actee) add(m.actee(), s.actee_pose);
  return box;
}

Camera frame_scene(const Model& m, const Eigen::AlignedBox3d& box, double aspect) {
  Camera c;
  const Eigen::Matrix3d r = m.object_start.linear();
  const Vector3d centre = box.center();
  const Vector3d back = (r * Vector3d(0, -0.55, 1)).normalized();  // from the target toward the eye
  c.up = r * Vector3d::UnitY();
  c.target = centre;
  // The camera's axes; every corner must fit inside 90 % of the view.
  const Vector3d fwd = -back;
  const Vector3d right = fwd.cross(c.up).normalized();
  const Vector3d up = right.cross(fwd);
  const double ty = std::tan(c.fov / 2) * 0.9, tx = ty * std::max(aspect, 1e-3);
  double dist = 1e-3;
  for (int i = 0; i < 8; ++i) {
    const Vector3d q = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - centre;
    const double depth = q.dot(fwd);  // toward the far side
    dist = std::max({dist, std::abs(q.dot(right)) / tx - depth, std::abs(q.dot(up)) / ty - depth});
  }
  c.position = centre + back * dist;
  return c;
}

double force_scale(const Model& m, const Eigen::AlignedBox3d& box) {
  const double f = std::max({m.has_actee ? m.actee_limit : 0.0, m.has_agent ? m.max_force : 0.0, 1.0});
  return 0.9 * (box.sizes().norm() / 2) / f;
}

Eigen::Vector2d project(const Camera& c, int w, int h, const Vector3d& world) {
  double n, f;
  clip_planes(c, &n, &f);
  const glm::vec4 clip =
      projection_of(c, static_cast<double>(w) / h, n, f) * view_of(c) * glm::vec4(vec(world), 1.0f);
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return {(x + 1) / 2 * w, (1 - y) / 2 * h};
}

struct Renderer::Impl {
  OSMesaContext ctx = nullptr;
  std::vector<unsigned char> buffer;  // RGBA, bottom row first
  Mesh shape, shards, extra, unit_sphere;
  // The last backdrop and what it was drawn for: a session's pictures keep
  // their camera and, while the tool stays, their ground.
  struct BackdropKey {
    Camera camera;
    int width = 0, height = 0;
    bool ground = false;
    Ground square;
    bool operator==(const BackdropKey&) const = default;
  };
  BackdropKey backdrop_key;
  Image backdrop;
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
  // Rasterise in the calling thread and keep no shader cache on disk: the
  // same pixels on every run, nothing written to $HOME, and no thread of
  // Mesa's alive at exit (LeakSanitizer's stop-the-world once crashed on
  // one in CI). As fast as one rasteriser thread: 2.63 against 2.72 s for
  // `afford render sessions/paper-nutcracker.yaml`, median of 3. The
  // environment may override either.
  setenv("LP_NUM_THREADS", "0", 0);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
  // A 16-bit depth buffer: half the memory to clear and test of 24 bits.
  // With the near plane at 0.05 of the target's distance d and the scene in
  // half the depth range, a step of depth there is d / 1638 (0.2 mm for the
  // nutcracker), finer than any gap the scenes show.
  impl_->ctx = gl().CreateContextExt(OSMESA_RGBA, 16, 0, 0, nullptr);
  if (impl_->ctx == nullptr) throw RenderError("OSMesa cannot create an offscreen OpenGL context");
  add_ellipsoid(impl_->unit_sphere, Vector3d::Ones(), 20, 10);
}

Renderer::~Renderer() {
  if (impl_->ctx == nullptr) return;
  if (gl().GetCurrentContext() == impl_->ctx) gl().MakeCurrent(nullptr, nullptr, 0, 0, 0);
  gl().DestroyContext(impl_->ctx);
}

Image Renderer::render(const Model& m, const State& s, const Camera& camera, const RenderOptions& o) {
  const int ss = std::clamp(o.supersample, 1, 4);
  const int w = o.width * ss, h = o.height * ss;
  if (o.width <= 0 || o.height <= 0 || w > 8192 || h > 8192) throw RenderError("image size out of range");
  Impl& im = *impl_;
  im.buffer.resize(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  if (!gl().MakeCurrent(im.ctx, im.buffer.data(), GL_UNSIGNED_BYTE, w, h)) {
    throw RenderError("OSMesa cannot make its context current");
  }
  const Eigen::AlignedBox3d box = scene_box(m, s);
  const double scene = std::max(box.sizes().norm() / 2, 0.02);  // m, a length for markers and arrows

  gl().Viewport(0, 0, w, h);
  // Translucent surfaces keep the picture's colour premultiplied by its
  // alpha, the cover, for the backdrop to show through them.
  gl().BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl().Disable(GL_DITHER);
  // Transparent where nothing is drawn: the backdrop (sky and ground) is
  // put under the picture afterwards (backdrop.h).
  gl().ClearColor(0, 0, 0, 0);
  gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // Contact markers and force arrows are drawn over the bodies they sit
  // in: the scene takes the far half of the depth range, they and the hand
  // the near half (a second clear of the depth buffer cost a full-screen
  // pass).
  const bool overlays = o.contacts || o.forces;
  gl().DepthRange(overlays ? 0.5 : 0.0, 1.0);

  double near_m, far_m;
  clip_planes(camera, &near_m, &far_m);
  gl().MatrixMode(GL_PROJECTION);
  gl().LoadMatrixf(glm::value_ptr(projection_of(camera, static_cast<double>(w) / h, near_m, far_m)));
  gl().MatrixMode(GL_MODELVIEW);
  gl().LoadIdentity();

  // Lights in eye space: a key light from the upper left, a fill from the right.
  gl().Enable(GL_LIGHTING);
  gl().Enable(GL_LIGHT0);
  gl().Enable(GL_LIGHT1);
  const GLfloat key_pos[] = {-0.45f, 0.6f, 1.0f, 0}, key_diffuse[] = {0.78f, 0.78f, 0.76f, 1},
                key_spec[] = {0.35f, 0.35f, 0.35f, 1};
  const GLfloat fill_pos[] = {0.7f, -0.2f, 0.6f, 0}, fill_diffuse[] = {0.28f, 0.30f, 0.34f, 1},
                none[] = {0, 0, 0, 1};
  const GLfloat ambient[] = {0.30f, 0.30f, 0.32f, 1};
  gl().Lightfv(GL_LIGHT0, GL_POSITION, key_pos);
  gl().Lightfv(GL_LIGHT0, GL_DIFFUSE, key_diffuse);
  gl().Lightfv(GL_LIGHT0, GL_SPECULAR, key_spec);
  gl().Lightfv(GL_LIGHT1, GL_POSITION, fill_pos);
  gl().Lightfv(GL_LIGHT1, GL_DIFFUSE, fill_diffuse);
  gl().Lightfv(GL_LIGHT1, GL_SPECULAR, none);
  gl().LightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  gl().LightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gl().Enable(GL_COLOR_MATERIAL);
  gl().ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  const GLfloat spec[] = {0.25f, 0.25f, 0.25f, 1};
  gl().Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  gl().Materialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
  gl().Enable(GL_NORMALIZE);
  gl().ShadeModel(GL_SMOOTH);

  gl().LoadMatrixf(glm::value_ptr(view_of(camera)));
  gl().Enable(GL_DEPTH_TEST);
  gl().DepthFunc(GL_LEQUAL);
  gl().Enable(GL_CULL_FACE);
  gl().CullFace(GL_BACK);
  gl().EnableClientState(GL_VERTEX_ARRAY);
  gl().EnableClientState(GL_NORMAL_ARRAY);

  // The acting object: every part on its arm.
  const Isometry3d moving = s.object_pose * moving_arm_pose(s.theta);
  for (const ModelPart& p : m.parts) {
    im.shape.clear();
    add_shape(im.shape, p.geometry);
    set_colour(p.arm == Arm::moving ? kMovingArm : kFixedArm);
    push_pose((p.arm == Arm::moving ? moving : s.object_pose) * p.in_arm);
    draw(im.shape);
    gl().PopMatrix();
  }

  // The actee, in the colours and the broken look of its file.
  if (m.has_actee) {
    im.shape.clear();
    add_shape(im.shape, m.actee());
    const ActeeLook& look = m.actee_look;
    const GlColour outside = colour_of(look.colour), inside = colour_of(look.inside);
    const double load = m.actee_limit > 0 ? std::clamp(s.actee_load / m.actee_limit, 0.0, 1.0) : 0.0;
    push_pose(s.actee_pose);
    if (s.condition == ActeeCondition::broken) {
      const Eigen::AlignedBox3d local = m.actee().local_box();
      const double size = local.sizes().minCoeff();
      const Vector3d d = m.actee_direction.normalized();
      // Toward the eye, in the actee's frame: the opened halves face it.
      const Vector3d eye =
          (s.actee_pose.linear().transpose() * (camera.position - s.actee_pose.translation())).normalized();
      if (look.broken == ActeeLook::Broken::halves) {
        split_open(im.shape, split_axis(local, d), eye, 0.45, 0.10 * size, im.shards);
      } else if (look.broken == ActeeLook::Broken::crushed) {
        // Flattened along A_d to 40 %, a little wider across; the inside
        // spills out between the pieces.
        squash_along(d, 0.4, 1.2);
        gl().PushMatrix();
        gl().Scaled(1.08, 1.08, 1.08);
        set_colour(inside);
        draw(im.shape);
        gl().PopMatrix();
        shatter(im.shape, 0.16 * size, im.shards);
      } else {
        shatter(im.shape, 0.13 * size, im.shards);
      }
      gl().CullFace(GL_FRONT);  // the inside of the shell, through the cracks
      set_colour(inside);
      draw(im.shards);
      gl().CullFace(GL_BACK);
      set_colour(mix(outside, GlColour{0, 0, 0}, 0.12f));  // a little darker: broken
      draw(im.shards);
    } else {
      // Flattened along A_d by the compression (half from each side),
      // widened across it to keep the volume.
      const Vector3d d = m.actee_direction.normalized();
      const double extent = std::max(m.actee().support(d), 1e-4);
      const double k = std::clamp(1 - s.actee_compression / (2 * extent), 0.3, 1.0);
      squash_along(d, k, 1 / std::sqrt(k));  // the volume kept
      const float tint = static_cast<float>(0.65 * load);
      set_colour(mix(outside, kStressed, tint));
      draw(im.shape);
    }
    gl().PopMatrix();
  }

  // Fingertips, opaque; the thumb in a deeper colour.
  if (m.has_agent) {
    for (int f = 0; f < kFingers; ++f) {
      const double r = m.tip_radius[static_cast<size_t>(f)];
      set_colour(f == 0 ? kThumb : kFinger);
      gl().PushMatrix();
      const Vector3d& p = s.fingertip[static_cast<size_t>(f)];
      gl().Translated(p.x(), p.y(), p.z());
      gl().Scaled(r, r, r);
      draw(im.unit_sphere);
      gl().PopMatrix();
    }
  }

  // The guides: lines (the advantage map) with depth, surfaces translucent.
  std::vector<GuideLabel> labels;
  if (o.guides != nullptr) {
    const Guides g = posed_guides(*o.guides, s.theta, s.object_pose);
    gl().Disable(GL_LIGHTING);
    gl().Disable(GL_CULL_FACE);
    gl().LineWidth(static_cast<float>(3 * ss));
    gl().Begin(GL_LINES);
    for (const GuideSegment& seg : g.segments) {
      gl().Color4d(seg.colour.r, seg.colour.g, seg.colour.b, 1);
      gl().Vertex3d(seg.a.x(), seg.a.y(), seg.a.z());
      gl().Vertex3d(seg.b.x(), seg.b.y(), seg.b.z());
    }
    gl().End();
    gl().Enable(GL_BLEND);
    gl().DepthMask(GL_FALSE);
    gl().Begin(GL_TRIANGLES);
    for (const GuideMesh& mesh : g.meshes) {
      gl().Color4d(mesh.colour.r, mesh.colour.g, mesh.colour.b, mesh.colour.a);
      for (const std::array<int, 3>& t : mesh.triangles) {
        for (int k : t) {
          const Vector3d& v = mesh.vertices[static_cast<size_t>(k)];
          gl().Vertex3d(v.x(), v.y(), v.z());
        }
      }
    }
    gl().End();
    gl().Begin(GL_QUADS);
    for (const GuideRect& r : g.rects) {
      gl().Color4d(r.colour.r, r.colour.g, r.colour.b, r.colour.a);
      for (const auto& [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        const Vector3d v = r.centre + a * r.half_u * r.u + b * r.half_v * r.v;
        gl().Vertex3d(v.x(), v.y(), v.z());
      }
    }
    gl().End();
    gl().DepthMask(GL_TRUE);
    gl().Disable(GL_BLEND);
    gl().Enable(GL_CULL_FACE);
    gl().Enable(GL_LIGHTING);
    labels = g.labels;
  }

  // Contact points and force arrows (drawn over the bodies they sit in).
  if (overlays) gl().DepthRange(0.0, 0.5);
  if (o.contacts) {
    const double r = scene * 0.022;
    auto markers = [&](const ContactSet& set, const GlColour& c) {
      set_colour(c);
      for (int i = 0; i < std::min(set.count, kMaxContacts); ++i) {
        const Vector3d& p = set.point[static_cast<size_t>(i)].point;
        gl().PushMatrix();
        gl().Translated(p.x(), p.y(), p.z());
        gl().Scaled(r, r, r);
        draw(im.unit_sphere);
        gl().PopMatrix();
      }
    };
    markers(s.agent_object, kAgentContact);
    markers(s.agent_actee, kAgentContact);
    markers(s.object_actee, kObjectActeeContact);
  }
  if (o.forces) {
    const double per_newton = o.force_scale > 0 ? o.force_scale : force_scale(m, box);
    // Proportional to the force; a small force still gets a visible arrow.
    const double max_len = scene * 1.2, min_len = scene * 0.08, radius = scene * 0.012;
    if (s.grasped && s.effort_force > 1e-3) {
      const Vector3d dir = (s.object_pose.linear() * s.closing_direction).normalized();
      const double len = std::clamp(s.effort_force * per_newton, min_len, max_len);
      im.extra.clear();
      add_arrow(im.extra, s.thumb_proxy - dir * (len + m.tip_radius[0]), s.thumb_proxy - dir * m.tip_radius[0],
                radius);
      set_colour(kEffortArrow);
      draw(im.extra);
    }
    if (m.has_actee && s.actee_force > 1e-3 && s.condition != ActeeCondition::broken) {
      const double len = std::clamp(s.actee_force * per_newton, min_len, max_len);
      const Vector3d centre = s.actee_pose.translation();
      im.extra.clear();
      for (int i = 0; i < std::min(s.object_actee.count, kMaxContacts); ++i) {
        const ContactPoint& c = s.object_actee.point[static_cast<size_t>(i)];
        Vector3d out = c.normal;
        if (out.dot(c.point - centre) < 0) out = -out;  // away from the actee: the jaw pushes inward
        add_arrow(im.extra, c.point + out * len, c.point, radius);
      }
      set_colour(kActeeArrow);
      draw(im.extra);
    }
  }

  // The hand, translucent, last: the palm box and the fingers. With the
  // agent's reach each finger is its chain of links (engine/model/reach.h), the
  // joints where its kinematics put them; without it a straight finger
  // from a knuckle to the tip.
  if (o.hand && m.has_agent) {
    gl().Enable(GL_BLEND);
    gl().DepthMask(GL_FALSE);
    im.extra.clear();
    add_box(im.extra, kPalmSize, kPalmCentre);
    const Isometry3d to_hand = s.hand.inverse();
    for (int f = 0; f < kFingers; ++f) {
      const double tip_radius = m.tip_radius[static_cast<size_t>(f)];
      const Vector3d tip = to_hand * s.fingertip[static_cast<size_t>(f)];
      if (m.has_reach) {
        const FingerChain chain = finger_chain(m, f, tip);
        for (size_t j = 0; j + 1 < chain.point.size(); ++j) {
          const Vector3d along = chain.point[j + 1] - chain.point[j];
          const bool last = j + 2 == chain.point.size();  // the tip's sphere ends the last link
          if (along.norm() > 1e-3) {
            const Vector3d end = chain.point[j + 1] - along.normalized() * (last ? tip_radius * 0.5 : 0.0);
            add_tube(im.extra, chain.point[j], end, kFingerRadius);
          }
        }
        continue;
      }
      const Vector3d along = tip - kKnuckle[f];
      if (along.norm() > 1e-3) add_tube(im.extra, kKnuckle[f], tip - along.normalized() * tip_radius * 0.5, kFingerRadius);
    }
    set_colour(kHand);
    push_pose(s.hand);
    draw(im.extra);
    gl().PopMatrix();
    gl().DepthMask(GL_TRUE);
    gl().Disable(GL_BLEND);
  }

  gl().DisableClientState(GL_VERTEX_ARRAY);
  gl().DisableClientState(GL_NORMAL_ARRAY);
  gl().Finish();

  // Ground: a pale square with a grid, under everything.
  Ground ground;
  if (o.ground) {
    ground.step = box.sizes().maxCoeff() > 0.4 ? 0.05 : 0.01;
    const Vector3d c = box.center();
    const double half = std::ceil(std::max(box.sizes().x(), box.sizes().y()) * 1.5 / ground.step) * ground.step;
    ground.x0 = std::floor((c.x() - half) / ground.step) * ground.step;
    ground.y0 = std::floor((c.y() - half) / ground.step) * ground.step;
    ground.z = o.ground_z;
    ground.cells = static_cast<int>(std::lround(2 * half / ground.step));
  }
  const Impl::BackdropKey key{camera, o.width, o.height, o.ground, ground};
  if (im.backdrop.width == 0 || !(key == im.backdrop_key)) {
    im.backdrop = Backdrop(camera, o.width, o.height, o.ground ? &ground : nullptr).draw();
    im.backdrop_key = key;
  }
  Image out = from_gl_rgba(im.buffer.data(), w, h, ss, &im.backdrop);
  // Guide labels, at their anchors, moved down past the ones already placed.
  std::vector<Eigen::AlignedBox2i> placed;
  for (const GuideLabel& l : labels) {
    const Eigen::Vector2d p = project(camera, o.width, o.height, l.anchor);
    auto u8 = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
    const int scale = o.width >= 480 ? 2 : 1;
    const Rgb fg{u8(l.colour.r), u8(l.colour.g), u8(l.colour.b)};
    // Light colours on a dark box, dark ones on a white box; kept inside the picture.
    const bool light = 0.3 * fg.r + 0.59 * fg.g + 0.11 * fg.b > 150;
    const int tw = text_width(l.text, scale);
    const int x = std::clamp(static_cast<int>(p.x()) + 4 * scale, 2 * scale, std::max(2 * scale, o.width - tw - 2 * scale));
    int y = std::clamp(static_cast<int>(p.y()) - 3 * scale, 2 * scale, std::max(2 * scale, o.height - 10 * scale));
    const int lh = (kGlyphHeight + 3) * scale;
    for (int tries = 0; tries < 8; ++tries) {
      const Eigen::AlignedBox2i here(Eigen::Vector2i(x, y), Eigen::Vector2i(x + tw, y + lh));
      bool clear = true;
      for (const Eigen::AlignedBox2i& b : placed) clear = clear && !b.intersects(here);
      if (clear) break;
      y += lh;
    }
    placed.emplace_back(Eigen::Vector2i(x, y), Eigen::Vector2i(x + tw, y + lh));
    draw_label(out, x, y, l.text, fg, light ? Rgb{40, 44, 54} : Rgb{255, 255, 255}, scale, scale + 1);
  }
  return out;
}

}  // namespace afford::render

// Mesa's OSMesa keeps a few hundred bytes per context for the life of the
// process (a framebuffer the context was made current with); LeakSanitizer
// (the AFFORD_SANITIZE build) is told that these are not ours. The hook is
// only read by the sanitizer runtime.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
