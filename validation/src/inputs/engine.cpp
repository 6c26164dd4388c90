// Engine query families (engine.hpp): Box2D 2.4.1 worlds stepped at 60 Hz, their distance queries
// recorded verbatim. Three pieces, top to bottom: the b2Distance interposer, the query pool that
// samples `count` queries from the run, and the scenes.
#include "inputs/engine.hpp"

#include "inputs/rng.hpp"

#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/box2d.h>

#include <dlfcn.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

// --- The interposer ---------------------------------------------------------------------------
//
// libbox2d.so calls b2Distance through its PLT (objdump -d: `call ... <_Z10b2Distance...@plt>` in
// b2TimeOfImpact and b2TestOverlap), so the dynamic linker binds those calls to the first
// definition in the global scope: the executable's, when the executable defines the symbol and
// exports it. validation/CMakeLists.txt gives every program linking gjk2d_validation the link
// option --export-dynamic-symbol for it (`nm -D gjk-validate` lists it as T; GNU ld 2.40 exports it
// even without the option, because libbox2d.so in the link defines the same symbol, but nothing
// here relies on that). The definition below
// records the input when a capture is active on this thread and forwards to the library's own
// b2Distance, found with dlsym(RTLD_NEXT). checkB2DistanceInterposed() proves the binding by a
// call that can only reach us through libbox2d's PLT.

namespace gjkval
{
namespace
{
constexpr const char* kB2DistanceSymbol =
    "_Z10b2DistanceP16b2DistanceOutputP14b2SimplexCachePK15b2DistanceInput";
constexpr std::string_view kB2TimeOfImpactPrefix = "_Z14b2TimeOfImpact";

using B2DistanceFn = void (*)(b2DistanceOutput*, b2SimplexCache*, const b2DistanceInput*);

B2DistanceFn libraryB2Distance()
{
    static const B2DistanceFn fn =
        reinterpret_cast<B2DistanceFn>(::dlsym(RTLD_NEXT, kB2DistanceSymbol));
    return fn;
}

void onB2Distance(const b2DistanceInput& input, const void* caller);
} // namespace
} // namespace gjkval

void b2Distance(b2DistanceOutput* output, b2SimplexCache* cache, const b2DistanceInput* input)
{
    gjkval::onB2Distance(*input, __builtin_return_address(0));
    const auto real = gjkval::libraryB2Distance();
    if (real == nullptr || real == static_cast<gjkval::B2DistanceFn>(&::b2Distance))
    {
        // Unreachable through engineQueries (checkB2DistanceInterposed() threw first); a caller
        // that bypassed it must not get a silent non-answer.
        std::fputs("gjk2d: internal error: the interposed b2Distance cannot find libbox2d's\n",
                   stderr);
        std::abort();
    }
    real(output, cache, input);
}

namespace gjkval
{
namespace
{

// --- The query pool: `count` queries sampled uniformly from the run ----------------------------
//
// Reservoir sampling (Vitter's algorithm R) with the pool's own seeded Rng: every query of the run
// is equally likely to be kept, whatever the run's length, and the result is a function of the
// seed. Keeping every k-th query instead aliases with the contact list's fixed order (a pyramid
// of n contacts per step kept the same list positions at every step and never its ground contacts).

class QueryPool
{
  public:
    QueryPool(std::size_t count, std::uint64_t seed) : count_(count), rng_(seed) {}

    // make() is called only for a query that is kept (for now).
    template <class Make> void offer(Make make)
    {
        const std::uint64_t i = offered_++;
        if (i < count_)
        {
            kept_.push_back({i, make()});
            return;
        }
        const std::uint64_t j = rng_.next() % (i + 1);
        if (j < count_)
            kept_[std::size_t(j)] = {i, make()};
    }

    std::uint64_t offered() const { return offered_; }

    // The kept queries in the order the engine made them.
    std::vector<EngineQuery> pick()
    {
        if (kept_.size() != count_)
            throw std::logic_error(
                fmt::format("engine query pool: {} kept, {} wanted", kept_.size(), count_));
        std::sort(kept_.begin(), kept_.end(),
                  [](const Kept& x, const Kept& y) { return x.index < y.index; });
        std::vector<EngineQuery> out;
        out.reserve(count_);
        for (auto& k : kept_)
            out.push_back(std::move(k.query));
        return out;
    }

  private:
    struct Kept
    {
        std::uint64_t index; // position in the run
        EngineQuery query;
    };
    std::size_t count_;
    Rng rng_;
    std::uint64_t offered_ = 0;
    std::vector<Kept> kept_;
};

// A proxy's type, from what b2DistanceProxy::Set made of the shape.
const char* proxyType(const b2DistanceProxy& p)
{
    if (p.m_count == 1)
        return "circle";
    if (p.m_count == 2)
        return "edge";
    return p.m_radius > b2_polygonRadius ? "rounded" : "polygon";
}

// The engine's floats verbatim (float to double is exact). The radius is the one the query used:
// the proxy's m_radius with useRadii, else 0.
ShapeIn shapeOf(const b2DistanceProxy& proxy, const b2Transform& xf, bool useRadii)
{
    ShapeIn s;
    s.points.reserve(std::size_t(proxy.m_count));
    for (int i = 0; i < proxy.m_count; ++i)
        s.points.push_back({double(proxy.m_vertices[i].x), double(proxy.m_vertices[i].y)});
    s.radius = useRadii ? double(proxy.m_radius) : 0.0;
    s.px = double(xf.p.x);
    s.py = double(xf.p.y);
    s.c = double(xf.q.c);
    s.s = double(xf.q.s);
    return s;
}

EngineQuery queryOf(const b2DistanceInput& in, int step)
{
    EngineQuery q;
    q.c.a = shapeOf(in.proxyA, in.transformA, in.useRadii);
    q.c.b = shapeOf(in.proxyB, in.transformB, in.useRadii);
    q.step = step;
    q.useRadii = in.useRadii;
    q.tag = fmt::format("step{}-{}-{}", step, proxyType(in.proxyA), proxyType(in.proxyB));
    return q;
}

// --- Capture of b2TimeOfImpact's b2Distance calls ----------------------------------------------

struct Capture
{
    QueryPool* pool = nullptr;
    int step = 0;
    std::uint64_t otherCalls = 0; // b2Distance calls from elsewhere (b2TestOverlap: sensors)
    std::unordered_map<const void*, bool> fromToi; // return address -> inside b2TimeOfImpact?

    bool calledFromTimeOfImpact(const void* caller)
    {
        auto it = fromToi.find(caller);
        if (it == fromToi.end())
        {
            Dl_info info{};
            const bool toi = ::dladdr(caller, &info) != 0 && info.dli_sname != nullptr &&
                             std::string_view(info.dli_sname).starts_with(kB2TimeOfImpactPrefix);
            it = fromToi.emplace(caller, toi).first;
        }
        return it->second;
    }
};

thread_local Capture* tCapture = nullptr;
thread_local std::uint64_t tCalls = 0;

void onB2Distance(const b2DistanceInput& input, const void* caller)
{
    ++tCalls;
    Capture* cap = tCapture;
    if (cap == nullptr)
        return;
    if (!cap->calledFromTimeOfImpact(caller))
    {
        ++cap->otherCalls;
        return;
    }
    cap->pool->offer([&] { return queryOf(input, cap->step); });
}

// Active for one world step; restores the previous capture however the step ends.
class CaptureScope
{
  public:
    CaptureScope(Capture* c, int step) : previous_(tCapture)
    {
        if (c != nullptr)
            c->step = step;
        tCapture = c;
    }
    ~CaptureScope() { tCapture = previous_; }
    CaptureScope(const CaptureScope&) = delete;
    CaptureScope& operator=(const CaptureScope&) = delete;

  private:
    Capture* previous_;
};

// Proximity: the query an engine makes on each contact of the list after a step.
void recordContacts(b2World& world, QueryPool& pool, int step)
{
    for (b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext())
        pool.offer(
            [&]
            {
                b2DistanceInput in;
                in.proxyA.Set(c->GetFixtureA()->GetShape(), c->GetChildIndexA());
                in.proxyB.Set(c->GetFixtureB()->GetShape(), c->GetChildIndexB());
                in.transformA = c->GetFixtureA()->GetBody()->GetTransform();
                in.transformB = c->GetFixtureB()->GetBody()->GetTransform();
                in.useRadii = true;
                return queryOf(in, step);
            });
}

// --- The scenes ---------------------------------------------------------------------------------
//
// Each builds its bodies from the seeded Rng and returns what it does after every step. Sleeping is
// off in every world: resting bodies keep being simulated (and queried), so that a long run does
// not repeat one frozen pose.

using StepAction = std::function<void(b2World&, int step)>;

constexpr float kTimeStep = 1.0f / 60.0f;
constexpr int kVelocityIterations = 8; // the testbed's defaults
constexpr int kPositionIterations = 3;
constexpr double kPi = std::numbers::pi;

// The testbed's ground: an 80 m two-sided edge on a static body.
void groundEdge(b2World& world)
{
    b2BodyDef bd;
    b2Body* ground = world.CreateBody(&bd);
    b2EdgeShape edge;
    edge.SetTwoSided(b2Vec2(-40.0f, 0.0f), b2Vec2(40.0f, 0.0f));
    ground->CreateFixture(&edge, 0.0f);
}

b2Body* dynamicBody(b2World& world, double x, double y, double angle)
{
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.position.Set(float(x), float(y));
    bd.angle = float(angle);
    return world.CreateBody(&bd);
}

// A convex n-gon (3 <= n <= 8) of circumradius r: vertices at evenly spaced angles, each moved by
// at most a quarter of the spacing (no two closer than b2PolygonShape::Set's weld distance).
b2PolygonShape ngon(Rng& rng, int n, double r)
{
    const double phase = rng.range(0, 2 * kPi), step = 2 * kPi / n;
    b2Vec2 v[b2_maxPolygonVertices];
    for (int i = 0; i < n; ++i)
    {
        const double a = phase + i * step + rng.range(-0.25, 0.25) * step;
        v[i].Set(float(r * std::cos(a)), float(r * std::sin(a)));
    }
    b2PolygonShape s;
    s.Set(v, n);
    return s;
}

// The testbed's pyramid (boxes of half size 0.5, 20 rows, start (-7, 0.75), row step (0.5625,
// 1.25), box step (1.125, 0)), scaled to a random box size, with a random row count, offset and a
// jitter of each box's position and angle.
StepAction buildPyramid(b2World& world, Rng& r)
{
    groundEdge(world);
    const double h = r.range(0.3, 0.6), k = 2 * h; // k: scale against the testbed's boxes
    const int rows = r.integer(10, 20);
    const double x0 = r.range(-15, 5);
    b2PolygonShape box;
    box.SetAsBox(float(h), float(h));
    for (int i = 0; i < rows; ++i)
        for (int j = i; j < rows; ++j)
        {
            const double x = x0 + i * 0.5625 * k + (j - i) * 1.125 * k + r.range(-0.02, 0.02) * k;
            const double y = 0.75 * k + i * 1.25 * k;
            dynamicBody(world, x, y, r.range(-0.01, 0.01))->CreateFixture(&box, 5.0f);
        }
    return [](b2World&, int) {};
}

// A kinematic box container (inner half size L, walls 1 thick) turning at a constant rate, filled
// on a grid of 1 m cells with polygons (3..8-gons), circles and rounded polygons (a 3..8-gon core
// whose m_radius, 0.05 .. 0.25, is larger than b2_polygonRadius = 0.01).
StepAction buildContainer(b2World& world, Rng& r)
{
    const double L = r.range(5, 8), cy = L + 1; // inner half size, the centre's height
    b2BodyDef bd;
    bd.type = b2_kinematicBody;
    bd.position.Set(0.0f, float(cy));
    bd.angularVelocity = float(r.sign() * r.range(0.15, 0.5));
    b2Body* container = world.CreateBody(&bd);
    const float w = float(L + 0.5);
    b2PolygonShape wall;
    wall.SetAsBox(0.5f, w + 0.5f, b2Vec2(w, 0.0f), 0.0f);
    container->CreateFixture(&wall, 5.0f);
    wall.SetAsBox(0.5f, w + 0.5f, b2Vec2(-w, 0.0f), 0.0f);
    container->CreateFixture(&wall, 5.0f);
    wall.SetAsBox(w + 0.5f, 0.5f, b2Vec2(0.0f, w), 0.0f);
    container->CreateFixture(&wall, 5.0f);
    wall.SetAsBox(w + 0.5f, 0.5f, b2Vec2(0.0f, -w), 0.0f);
    container->CreateFixture(&wall, 5.0f);

    const int cells = int(2 * L - 1); // cells per row, centres at least 1 from the walls' faces
    const double fill = r.range(0.35, 0.55);
    for (int iy = 0; iy < cells; ++iy)
        for (int ix = 0; ix < cells; ++ix)
        {
            if (r.uniform() > fill)
                continue;
            const double x = -L + 1 + ix, y = cy - L + 1 + iy;
            b2Body* body = dynamicBody(world, x, y, r.range(0, 2 * kPi));
            b2FixtureDef fd;
            fd.density = 1.0f;
            fd.friction = 0.6f;
            const double u = r.uniform();
            if (u < 0.35)
            {
                const b2PolygonShape s = ngon(r, r.integer(3, 8), r.range(0.15, 0.48));
                fd.shape = &s;
                body->CreateFixture(&fd);
            }
            else if (u < 0.65)
            {
                b2CircleShape s;
                s.m_radius = float(r.range(0.1, 0.48));
                fd.shape = &s;
                body->CreateFixture(&fd);
            }
            else
            {
                const double rounding = r.range(0.05, 0.25);
                b2PolygonShape s = ngon(r, r.integer(3, 8), r.range(0.1, 0.48 - rounding));
                s.m_radius = float(rounding);
                fd.shape = &s;
                body->CreateFixture(&fd);
            }
        }
    return [](b2World&, int) {};
}

// A stack of boxes (2..4 columns of 5..10) on the ground; every 15..40 steps a bullet (a circle, a
// box or a rounded box, 0.05 .. 0.25) is fired from x = -20 at 40..120 m/s (Box2D clamps a step's
// translation at b2_maxTranslation = 2 m, i.e. 120 m/s at 60 Hz) at a height within the stack's,
// angle within +-0.1 rad; at most 20 bullets live, the oldest is removed.
StepAction buildBullets(b2World& world, Rng& r)
{
    groundEdge(world);
    const double h = r.range(0.25, 0.5);
    const int columns = r.integer(2, 4), rows = r.integer(5, 10);
    const double gap = r.range(0.1, 1.0) * h;
    b2PolygonShape box;
    box.SetAsBox(float(h), float(h));
    for (int c = 0; c < columns; ++c)
        for (int i = 0; i < rows; ++i)
            dynamicBody(world, 2 + c * (2 * h + gap) + r.range(-0.05, 0.05) * h,
                        h + i * 2 * h + 0.005 * i, 0)
                ->CreateFixture(&box, 1.0f);
    const double top = rows * 2 * h;
    const int period = r.integer(15, 40);
    auto bullets = std::make_shared<std::deque<b2Body*>>();
    return [r, top, period, bullets](b2World& w, int step) mutable
    {
        if (step % period != 0)
            return;
        const double angle = r.range(-0.1, 0.1), speed = r.range(40, 120);
        b2BodyDef bd;
        bd.type = b2_dynamicBody;
        bd.bullet = true;
        bd.position.Set(-20.0f, float(r.range(0.3, top)));
        bd.linearVelocity.Set(float(speed * std::cos(angle)), float(speed * std::sin(angle)));
        bd.angularVelocity = float(r.range(-10, 10));
        b2Body* bullet = w.CreateBody(&bd);
        const double size = r.range(0.05, 0.25), u = r.uniform();
        const float density = float(r.range(2, 20));
        if (u < 0.4)
        {
            b2CircleShape s;
            s.m_radius = float(size);
            bullet->CreateFixture(&s, density);
        }
        else
        {
            b2PolygonShape s;
            s.SetAsBox(float(size), float(size * r.range(0.5, 1)));
            if (u > 0.7)
                s.m_radius = float(r.range(0.02, 0.1));
            bullet->CreateFixture(&s, density);
        }
        bullets->push_back(bullet);
        if (bullets->size() > 20)
        {
            w.DestroyBody(bullets->front());
            bullets->pop_front();
        }
    };
}

std::string familyLabel(EngineScene scene, EngineQueryKind kind)
{
    return fmt::format("engine/{}-{}", kEngineSceneNames[int(scene)],
                       kEngineQueryKindNames[int(kind)]);
}

} // namespace

std::uint64_t interposedB2DistanceCalls()
{
    return tCalls;
}

void checkB2DistanceInterposed()
{
    const B2DistanceFn real = libraryB2Distance();
    if (real == nullptr)
        throw std::logic_error(fmt::format(
            "engine families: dlsym(RTLD_NEXT, \"{}\") found no b2Distance after this program's "
            "(is libbox2d.so linked?)",
            kB2DistanceSymbol));
    if (real == static_cast<B2DistanceFn>(&::b2Distance))
        throw std::logic_error("engine families: dlsym(RTLD_NEXT) found the interposer itself, "
                               "not libbox2d's b2Distance");
    // b2TestOverlap (libbox2d) calls b2Distance through libbox2d's PLT: the call reaches us only
    // when the dynamic linker bound it to this program's exported definition.
    const std::uint64_t before = tCalls;
    b2CircleShape circle;
    circle.m_radius = 1.0f;
    b2Transform xf;
    xf.SetIdentity();
    const bool overlap = b2TestOverlap(&circle, 0, &circle, 0, xf, xf);
    if (tCalls == before)
        throw std::logic_error(fmt::format(
            "engine families: libbox2d.so's own call of b2Distance (from b2TestOverlap) did not "
            "reach the interposer: this program does not export {} (check with nm -D; programs "
            "get it by linking gjk2d_validation, whose link options export it)",
            kB2DistanceSymbol));
    if (!overlap)
        throw std::logic_error("engine families: b2TestOverlap of a circle with itself said "
                               "apart through the interposer");
}

std::vector<EngineQuery> engineQueries(EngineScene scene, EngineQueryKind kind, std::uint64_t seed,
                                       int count)
{
    if (count < 1)
        throw std::logic_error(fmt::format("engineQueries: count {} < 1", count));
    const bool toi = kind == EngineQueryKind::Toi;
    if (toi)
        checkB2DistanceInterposed();

    Rng r(seed);
    b2World world(b2Vec2(0.0f, -10.0f));
    world.SetAllowSleeping(false);
    StepAction after;
    switch (scene)
    {
    case EngineScene::Pyramid:
        after = buildPyramid(world, r);
        break;
    case EngineScene::Container:
        after = buildContainer(world, r);
        break;
    case EngineScene::Bullets:
        after = buildBullets(world, r);
        break;
    }

    QueryPool pool{std::size_t(count), mix64(seed ^ 0x706f6f6c)}; // its own stream: "pool"
    Capture capture;
    capture.pool = &pool;
    const long long maxSteps = kEngineMinSteps + (long long)kEngineMaxStepsPerQuery * count;
    for (long long step = 1;; ++step)
    {
        if (step > maxSteps)
            throw std::logic_error(fmt::format(
                "{}: {} queries after {} steps, {} wanted: the scene stopped making queries",
                familyLabel(scene, kind), pool.offered(), maxSteps, count));
        {
            CaptureScope scope(toi ? &capture : nullptr, int(step));
            world.Step(kTimeStep, kVelocityIterations, kPositionIterations);
        }
        if (!toi)
            recordContacts(world, pool, int(step));
        after(world, int(step));
        if (step == kEngineMinSteps && pool.offered() == 0)
            throw std::logic_error(fmt::format(
                "{}: no query in {} steps{}", familyLabel(scene, kind), kEngineMinSteps,
                toi ? " (b2TimeOfImpact's b2Distance calls are not reaching the interposer)" : ""));
        if (step >= kEngineMinSteps && pool.offered() >= std::uint64_t(count))
            break;
    }
    return pool.pick();
}

} // namespace gjkval
