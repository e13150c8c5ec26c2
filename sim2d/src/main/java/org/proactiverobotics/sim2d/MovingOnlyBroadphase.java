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
 */
final class MovingOnlyBroadphase extends BroadphaseDetectorDecoratorAdapter<CollisionItem<Body, BodyFixture>> {

    private final List<CollisionItem<Body, BodyFixture>> moving = new ArrayList<>();

    MovingOnlyBroadphase(BroadphaseDetector<CollisionItem<Body, BodyFixture>> detector) {
        super(detector);
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
    }

    @Override
    public void update() {
        for (int i = 0; i < moving.size(); i++) {
            super.update(moving.get(i));
        }
    }
}
