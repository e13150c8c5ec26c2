package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.Station;

/**
 * Whether the recharge station is taken, as the rays see it: the robot is within
 * {@value #NEAR_M} m of the station (and not on it), and a ray stops short of the station on
 * something within {@value #TAKEN_M} m of its centre. A wall beyond the station is hit after the
 * ray passed it, so a station in a corner is not taken; a robot on it is hit on its near side.
 */
final class StationView {

    /** The robot waits for a taken station from this near, metres from its centre. */
    static final double NEAR_M = 1.2;
    /** Something this near the station's centre takes it, metres (a body on it: its centre within the station's reach, its rim beyond). */
    static final double TAKEN_M = 0.3;
    /** The decision's prefix while the battery scenario drives the robot (DecisionMaking writes "scenario command"). */
    static final String BATTERY_DRIVES = "BatteryMonitor ";

    private StationView() {
    }

    /** @return whether the last decision was the battery scenario's, driving (not charging) */
    static boolean headingThere(String lastDecision) {
        return lastDecision.startsWith(BATTERY_DRIVES) && !lastDecision.endsWith(" RECHARGE");
    }

    /**
     * @param station the station, or null
     * @param pose    the robot's pose at the scan
     * @param scan    the scan
     * @param radiusM the robot's radius (the rays start at its rim), metres
     * @return whether the robot is near the station, not on it, and a ray stops on something that takes it
     */
    static boolean taken(Station station, PoseEstimate pose, DistanceScan scan, double radiusM) {
        if (station == null) {
            return false;
        }
        double toStation = pose.distanceTo(station.xM(), station.yM());
        if (toStation > NEAR_M || toStation < station.radiusM()) {
            return false;
        }
        for (int k = 0; k < scan.anglesRad().length; k++) {
            double d = scan.distancesM()[k];
            if (!(d >= 0) || d >= scan.rangeM() * (1 - Oncoming.FREE_MARGIN)) {
                continue;
            }
            double a = pose.yawRad() + scan.anglesRad()[k];
            double hx = pose.xM() + Math.cos(a) * (radiusM + d);
            double hy = pose.yM() + Math.sin(a) * (radiusM + d);
            boolean nearStation = Math.hypot(hx - station.xM(), hy - station.yM()) <= TAKEN_M;
            // short of the station along the ray: what is hit stands between the robot and the station's centre
            double along = (station.xM() - pose.xM()) * Math.cos(a) + (station.yM() - pose.yM()) * Math.sin(a);
            if (nearStation && radiusM + d < along) {
                return true;
            }
        }
        return false;
    }
}
