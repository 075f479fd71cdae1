#include "rt/accel/fast_traversal.h"

#include <unordered_map>

#include "rt/accel/wide_bvh.h"
#include "rt/geometry/instance.h"
#include "rt/scene/hittable_list.h"

namespace rt {

namespace {

// One rewrite of a world: each object is looked at once, so an object placed twice (one box in
// two instances) stays one object.
class rewrite {
  public:
    rewrite(const std::vector<leaf_shapes_maker>& kinds, const std::vector<tree_packer>& own)
        : extra_kinds(kinds), packers(own) {}

    std::shared_ptr<hittable> operator()(const std::shared_ptr<hittable>& object) {
        if (!object) return object;
        auto [done, fresh] = rewritten.try_emplace(object.get());
        if (fresh) done->second = faster(object);
        return done->second;
    }

  private:
    // Exactly these types: a class derived from one of them may behave differently, and keeps
    // its own.
    std::shared_ptr<hittable> faster(const std::shared_ptr<hittable>& object) {
        const hittable& o = *object;
        if (typeid(o) == typeid(bvh)) {
            for (const tree_packer& pack : packers)
                if (auto packed = pack(std::static_pointer_cast<const bvh>(object))) return packed;
            return std::make_shared<wide_bvh>(
                static_cast<const bvh&>(o),
                [this](const std::shared_ptr<hittable>& leaf) { return (*this)(leaf); },
                extra_kinds);
        }
        if (typeid(o) == typeid(hittable_list)) {
            const auto& list = static_cast<const hittable_list&>(o);
            auto copy        = std::make_shared<hittable_list>();
            bool changed     = false;
            for (const auto& member : list.objects) {
                copy->add((*this)(member));
                changed = changed || copy->objects.back() != member;
            }
            return changed ? copy : object;
        }
        // Instances hold bounded objects; what replaces one is a bounded_hittable with the
        // same box (a wide_bvh, or an instance placed again), so the instance's box is the same.
        if (typeid(o) == typeid(translate)) {
            const auto& t = static_cast<const translate&>(o);
            auto inside   = (*this)(t.placed());
            if (inside == t.placed()) return object;
            return std::make_shared<translate>(bounded(inside), t.displacement());
        }
        if (typeid(o) == typeid(rotate)) {
            const auto& t = static_cast<const rotate&>(o);
            auto inside   = (*this)(t.placed());
            if (inside == t.placed()) return object;
            return std::make_shared<rotate>(bounded(inside), t.turned_about(), t.degrees());
        }
        return object;
    }

    // What replaced an instance's object: a wide_bvh or an instance, both bounded_hittables
    // (an instance can hold nothing unbounded, such as a list).
    static bounded_object bounded(const std::shared_ptr<hittable>& replaced) {
        return bounded_object(std::static_pointer_cast<bounded_hittable>(replaced));
    }

    const std::vector<leaf_shapes_maker>& extra_kinds;
    const std::vector<tree_packer>& packers;
    std::unordered_map<const hittable*, std::shared_ptr<hittable>> rewritten;
};

}  // namespace

std::shared_ptr<hittable> with_wide_bvhs(const std::shared_ptr<hittable>& world,
                                         const std::vector<leaf_shapes_maker>& extra_kinds,
                                         const std::vector<tree_packer>& packers) {
    return rewrite(extra_kinds, packers)(world);
}

scene with_fast_traversal(scene s, const std::vector<leaf_shapes_maker>& extra_kinds,
                          const std::vector<tree_packer>& packers) {
    s.world = with_wide_bvhs(s.world, extra_kinds, packers);
    return s;
}

}  // namespace rt
