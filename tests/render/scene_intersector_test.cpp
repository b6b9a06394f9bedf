// scene_intersector_test.cpp — the reference's ray queries are pluggable: SceneTracer counts and
// forwards every query, and a render through another intersector that gives the same answers
// (brute force) gives the same image, so that embree-ref's images differ from vkpt-ref's only by
// what Embree answers.
#include <gtest/gtest.h>

#include <vector>

#include "../support/reference_render.h"
#include "reference/scene_tracer.h"
#include "reference/stack_intersector.h"

namespace vkpt::scene_intersector_test {
namespace {

// Every primitive tested for every ray (bvh_traverse.h's brute force), with the alpha test.
class BruteForceIntersectors final : public IntersectorFactory {
public:
    explicit BruteForceIntersectors(const PreparedScene& scene)
        : scene_(scene), alphaMask_(scene) {}

    std::unique_ptr<SceneIntersector> makeIntersector() const override {
        return std::make_unique<Intersector>(*this);
    }

private:
    class Intersector final : public SceneIntersector {
    public:
        explicit Intersector(const BruteForceIntersectors& owner) : owner_(owner) {}
        ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                              float tMin) override {
            return owner_.query({origin, direction, tMin, VKPT_FAR});
        }
        bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
            return owner_.query({origin, direction, 0.0f, tMax}).hit;
        }

    private:
        const BruteForceIntersectors& owner_;
    };

    ClosestHit query(RayQuery ray) const {
        ray.filter = &alphaMask_;
        return closestHitBruteForce(scene_.triangles, ray);
    }

    const PreparedScene& scene_;
    AlphaMaskFilter alphaMask_;
};

// Writes down the queries it gets and answers "nothing there".
struct RecordedQuery {
    glm::vec3 origin;
    glm::vec3 direction;
    float tMax;
};

class RecordingIntersectors final : public IntersectorFactory {
public:
    std::unique_ptr<SceneIntersector> makeIntersector() const override {
        return std::make_unique<Intersector>(queries);
    }
    mutable std::vector<RecordedQuery> queries;

private:
    class Intersector final : public SceneIntersector {
    public:
        explicit Intersector(std::vector<RecordedQuery>& queries) : queries_(queries) {}
        ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                              float /*tMin*/) override {
            queries_.push_back({origin, direction, VKPT_FAR});
            return {};
        }
        bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
            queries_.push_back({origin, direction, tMax});
            return false;
        }

    private:
        std::vector<RecordedQuery>& queries_;
    };
};

TEST(SceneTracer, CountsRaysByKindAndForwardsEachQuery) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RecordingIntersectors recorder;
    SceneTracer tracer(box.prepared, recorder);
    const glm::vec3 o(0.1f, 0.2f, 0.3f), d(0.0f, 0.0f, -1.0f);
    EXPECT_FALSE(tracer.closest(o, d, RayKind::Camera).hit);
    EXPECT_FALSE(tracer.closest(o, d, RayKind::Extension).hit);
    EXPECT_FALSE(tracer.occluded(o, d, 0.5f));
    EXPECT_EQ(tracer.rays().camera, 1u);
    EXPECT_EQ(tracer.rays().extension, 1u);
    EXPECT_EQ(tracer.rays().shadow, 1u);
    ASSERT_EQ(recorder.queries.size(), 3u);
    EXPECT_EQ(recorder.queries[2].origin, o);
    EXPECT_EQ(recorder.queries[2].direction, d);
    EXPECT_EQ(recorder.queries[2].tMax, 0.5f);
    EXPECT_EQ(tracer.traversal().nodesVisited, 0u) << "work the intersector does not count";
}

// glTF's doubleSided false: a camera ray passes the back of a single-sided surface (the
// emission-sides quad whose back faces the camera; the room's near wall) and meets what lies
// beyond; extension and shadow rays meet both sides, and a double-sided surface stops the camera.
TEST(SceneTracer, CameraRaysPassTheBackOfSingleSidedSurfacesOnly) {
    test::LoadedTestScene sides = test::loadTestScene("test/emission-sides.gltf");
    StackIntersectors stack(sides.prepared);
    SceneTracer tracer(sides.prepared, stack);
    const glm::vec3 eye(0.0f, 0.0f, 2.5f);
    const glm::vec3 toBack = glm::vec3(0.5f, 0.5f, 0.0f) - eye; // single-sided, back to the eye
    const glm::vec3 toDoubleSided = glm::vec3(0.0f, -0.5f, 0.0f) - eye;
    const glm::vec3 toFront = glm::vec3(-0.5f, 0.5f, 0.0f) - eye;
    EXPECT_FALSE(tracer.closest(eye, toBack, RayKind::Camera).hit);
    EXPECT_TRUE(tracer.closest(eye, toBack, RayKind::Extension).hit);
    EXPECT_TRUE(tracer.occluded(eye, toBack, 2.0f));
    EXPECT_TRUE(tracer.closest(eye, toDoubleSided, RayKind::Camera).hit);
    EXPECT_TRUE(tracer.closest(eye, toFront, RayKind::Camera).hit);

    test::LoadedTestScene room = test::loadTestScene("test/single-sided-room.gltf");
    StackIntersectors roomStack(room.prepared);
    SceneTracer roomTracer(room.prepared, roomStack);
    const glm::vec3 outside(0.0f, 1.0f, 3.2f), ahead(0.0f, 0.0f, -1.0f);
    EXPECT_NEAR(roomTracer.closest(outside, ahead, RayKind::Camera).t, 4.2f, 1e-5f)
        << "the back wall, through the near wall";
    EXPECT_NEAR(roomTracer.closest(outside, ahead, RayKind::Extension).t, 2.2f, 1e-5f)
        << "the near wall";
}

TEST(SceneIntersector, SameAnswersGiveTheSameImage) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(16, 4);
    settings.maxDepth = 8;
    gpu::Camera camera = makeGpuCamera(selectCamera(box.scene, {}), 16, 16);
    RenderStats stackStats, bruteStats;
    StackIntersectors stack(box.prepared);
    BruteForceIntersectors brute(box.prepared);
    RenderOutput viaStack = renderReference(box.prepared, camera, settings, stackStats, stack);
    RenderOutput viaBrute = renderReference(box.prepared, camera, settings, bruteStats, brute);
    EXPECT_EQ(viaStack.image.pixels, viaBrute.image.pixels);
    EXPECT_EQ(stackStats.rays.total(), bruteStats.rays.total());
    EXPECT_GT(stackStats.nodesVisited, 0u);
    EXPECT_EQ(bruteStats.nodesVisited, 0u);
    RenderStats defaultStats;
    RenderOutput viaDefault = renderReference(box.prepared, camera, settings, defaultStats);
    EXPECT_EQ(viaDefault.image.pixels, viaStack.image.pixels) << "the default is the stack walk";
}

} // namespace
} // namespace vkpt::scene_intersector_test
