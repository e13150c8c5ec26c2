package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.List;

import org.dyn4j.collision.CollisionItem;
import org.dyn4j.collision.broadphase.BroadphaseDetector;
import org.dyn4j.collision.broadphase.BroadphaseDetectorDecoratorAdapter;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;

/**
 * dyn4j's broadphase, except that a step refreshes only the fixtures of bodies that can move.
 * <p>
 * dyn4j recomputes every fixture's AABB on every step; here the arena wall and obstacles never move, so that
 * work grew with the obstacle count for nothing. Bodies must have their mass type set before being added.
 * <p>
 * Update tracking stays off until the first step's detection is over: dyn4j's tree otherwise records every
 * fixture added as updated, its map of updated fixtures grows to the obstacle count and never shrinks, and each
 * step's {@link #clearUpdates()} then clears a table that large (16 384 slots on a floor of 8 196 boxes). With
 * tracking off the first detection looks at every fixture, in the order they were added, exactly as it did with
 * every fixture marked updated, so the pairs found and their order are the same.
 */
final class MovingOnlyBroadphase extends BroadphaseDetectorDecoratorAdapter<CollisionItem<Body, BodyFixture>> {

    private final List<CollisionItem<Body, BodyFixture>> moving = new ArrayList<>();

    /** Whether the first detection is over and update tracking is on. */
    private boolean tracking;

    MovingOnlyBroadphase(BroadphaseDetector<CollisionItem<Body, BodyFixture>> detector) {
        super(detector);
        super.setUpdateTrackingEnabled(false);
    }

    @Override
    public void clearUpdates() {
        super.clearUpdates();
        if (!tracking) {
            // The first detection is over: from now on only what moves is recorded, in a map that stays small.
            tracking = true;
            super.setUpdateTrackingEnabled(true);
        }
    }

    @Override
    public void add(CollisionItem<Body, BodyFixture> item) {
        super.add(item);
        if (!item.getBody().isStatic()) {
            moving.add(item);
        }
    }

    @Override
    public boolean remove(CollisionItem<Body, BodyFixture> item) {
        moving.remove(item);
        return super.remove(item);
    }

    @Override
    public void clear() {
        moving.clear();
        super.clear();
        // Whatever is added next is all new again: the next detection looks at everything.
        tracking = false;
        super.setUpdateTrackingEnabled(false);
    }

    @Override
    public void update() {
        for (int i = 0; i < moving.size(); i++) {
            super.update(moving.get(i));
        }
    }
}
