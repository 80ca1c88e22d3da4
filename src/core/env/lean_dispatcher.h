#pragma once

#include <btBulletCollisionCommon.h>

namespace jetbot_rl {

/**
 * A btDispatcher for one small world that keeps only that world's contact manifolds.
 *
 * btCollisionDispatcher carries two 36 x 36 tables of algorithm factories (21 KiB), which would be
 * most of an env's memory; this one asks the collision configuration (shared by every env, only
 * read) for the factory instead, and otherwise behaves like btCollisionDispatcher for discrete
 * collision detection: same manifold thresholds and near-callback. Manifolds and algorithms are
 * the env's own allocations, not taken from the configuration's pools, so that any thread may
 * step the env and its contacts lie with its other data.
 */
class LeanDispatcher : public btDispatcher {
 public:
  explicit LeanDispatcher(btCollisionConfiguration* configuration)
      : configuration_(configuration) {}
  ~LeanDispatcher() override;
  LeanDispatcher(const LeanDispatcher&) = delete;
  LeanDispatcher& operator=(const LeanDispatcher&) = delete;

  btCollisionAlgorithm* findAlgorithm(const btCollisionObjectWrapper* body0,
                                      const btCollisionObjectWrapper* body1,
                                      btPersistentManifold* shared_manifold,
                                      ebtDispatcherQueryType query_type) override;
  btPersistentManifold* getNewManifold(const btCollisionObject* body0,
                                       const btCollisionObject* body1) override;
  void releaseManifold(btPersistentManifold* manifold) override;
  void clearManifold(btPersistentManifold* manifold) override { manifold->clearManifold(); }
  bool needsCollision(const btCollisionObject* body0, const btCollisionObject* body1) override;
  bool needsResponse(const btCollisionObject* body0, const btCollisionObject* body1) override;
  void dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                 btDispatcher* dispatcher) override;
  int getNumManifolds() const override { return manifolds_.size(); }
  btPersistentManifold* getManifoldByIndexInternal(int index) override { return manifolds_[index]; }
  btPersistentManifold** getInternalManifoldPointer() override {
    return manifolds_.size() ? &manifolds_[0] : nullptr;
  }
  btPoolAllocator* getInternalManifoldPool() override {
    return configuration_->getPersistentManifoldPool();
  }
  const btPoolAllocator* getInternalManifoldPool() const override {
    return configuration_->getPersistentManifoldPool();
  }
  void* allocateCollisionAlgorithm(int size) override;
  void freeCollisionAlgorithm(void* ptr) override;

 private:
  btCollisionConfiguration* configuration_;
  btAlignedObjectArray<btPersistentManifold*> manifolds_;
};

}  // namespace jetbot_rl
