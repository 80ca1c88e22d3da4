#include "env/lean_dispatcher.h"

#include <new>

namespace jetbot_rl {
namespace {

/// Runs narrow-phase collision detection on every overlapping pair, as Bullet's default
/// near-callback does for discrete stepping.
class NearCallback : public btOverlapCallback {
 public:
  NearCallback(LeanDispatcher& dispatcher, const btDispatcherInfo& info)
      : dispatcher_(dispatcher), info_(info) {}

  bool processOverlap(btBroadphasePair& pair) override {
    auto* object0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    auto* object1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (!dispatcher_.needsCollision(object0, object1)) return false;
    btCollisionObjectWrapper wrap0(nullptr, object0->getCollisionShape(), object0,
                                   object0->getWorldTransform(), -1, -1);
    btCollisionObjectWrapper wrap1(nullptr, object1->getCollisionShape(), object1,
                                   object1->getWorldTransform(), -1, -1);
    if (!pair.m_algorithm) {
      pair.m_algorithm =
          dispatcher_.findAlgorithm(&wrap0, &wrap1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    }
    if (pair.m_algorithm) {
      btManifoldResult result(&wrap0, &wrap1);
      pair.m_algorithm->processCollision(&wrap0, &wrap1, info_, &result);
    }
    return false;  // keep the pair
  }

 private:
  LeanDispatcher& dispatcher_;
  const btDispatcherInfo& info_;
};

}  // namespace

LeanDispatcher::~LeanDispatcher() {
  while (manifolds_.size()) releaseManifold(manifolds_[manifolds_.size() - 1]);
}

btCollisionAlgorithm* LeanDispatcher::findAlgorithm(const btCollisionObjectWrapper* body0,
                                                    const btCollisionObjectWrapper* body1,
                                                    btPersistentManifold* shared_manifold,
                                                    ebtDispatcherQueryType query_type) {
  btCollisionAlgorithmConstructionInfo info;
  info.m_dispatcher1 = this;
  info.m_manifold = shared_manifold;
  const int type0 = body0->getCollisionShape()->getShapeType();
  const int type1 = body1->getCollisionShape()->getShapeType();
  btCollisionAlgorithmCreateFunc* create =
      query_type == BT_CONTACT_POINT_ALGORITHMS
          ? configuration_->getCollisionAlgorithmCreateFunc(type0, type1)
          : configuration_->getClosestPointsAlgorithmCreateFunc(type0, type1);
  return create->CreateCollisionAlgorithm(info, body0, body1);
}

btPersistentManifold* LeanDispatcher::getNewManifold(const btCollisionObject* body0,
                                                     const btCollisionObject* body1) {
  // Bullet's default: relative breaking thresholds, the smaller of the two shapes' wins.
  const btScalar breaking =
      btMin(body0->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold),
            body1->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
  const btScalar processing =
      btMin(body0->getContactProcessingThreshold(), body1->getContactProcessingThreshold());
  void* memory = btAlignedAlloc(sizeof(btPersistentManifold), 16);
  auto* manifold = new (memory) btPersistentManifold(body0, body1, 0, breaking, processing);
  manifold->m_index1a = manifolds_.size();
  manifolds_.push_back(manifold);
  return manifold;
}

void LeanDispatcher::releaseManifold(btPersistentManifold* manifold) {
  clearManifold(manifold);
  const int index = manifold->m_index1a;
  manifolds_.swap(index, manifolds_.size() - 1);
  manifolds_[index]->m_index1a = index;
  manifolds_.pop_back();
  manifold->~btPersistentManifold();
  btAlignedFree(manifold);
}

bool LeanDispatcher::needsCollision(const btCollisionObject* body0,
                                    const btCollisionObject* body1) {
  if (!body0->isActive() && !body1->isActive()) return false;
  return body0->checkCollideWith(body1) && body1->checkCollideWith(body0);
}

bool LeanDispatcher::needsResponse(const btCollisionObject* body0, const btCollisionObject* body1) {
  return body0->hasContactResponse() && body1->hasContactResponse() &&
         (!body0->isStaticOrKinematicObject() || !body1->isStaticOrKinematicObject());
}

void LeanDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* pairs,
                                               const btDispatcherInfo& info,
                                               btDispatcher* dispatcher) {
  NearCallback callback(*this, info);
  pairs->processAllOverlappingPairs(&callback, dispatcher);
}

void* LeanDispatcher::allocateCollisionAlgorithm(int size) {
  return btAlignedAlloc(static_cast<size_t>(size), 16);
}

void LeanDispatcher::freeCollisionAlgorithm(void* ptr) { btAlignedFree(ptr); }

}  // namespace jetbot_rl
