#!/usr/bin/env python3
"""Sets hypotheses in the shipped kitchen on next_best_view and asks for the next best view, for
scripts/nbv_screenshot.sh: clouds of predicted poses around a cup on the table, a coffee box on
the counter and crisp bread on the shelf (seeded, so the picture is the same every time)."""
import math
import random

import rospy
from asr_msgs.msg import PredictedObjectPoses, PredictedPoseCloud, RobotState
from asr_msgs.srv import GetNextBestView, SetNbvHypotheses, UpdateNbvHypotheses
from geometry_msgs.msg import Pose

CLOUDS = [("Cup", 2.9, 2.4, 0.77, 0.12), ("CoffeeBox", 1.6, 4.6, 1.0, 0.15),
          ("Knaeckebrot", 0.25, 2.4, 1.2, 0.1)]


def pose(x, y, z, yaw):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.z, p.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


def main():
    rospy.init_node("nbv_screenshot_request")
    random.seed(4)
    cloud = PredictedPoseCloud()
    cloud.header.frame_id = "map"
    cloud.scene = "breakfast"
    for kind, x, y, z, spread in CLOUDS:
        poses = PredictedObjectPoses(type=kind, instance_id="0")
        poses.poses = [pose(random.gauss(x, spread), random.gauss(y, spread), z,
                            random.gauss(0.0, 0.8)) for _ in range(150)]
        cloud.objects.append(poses)
    rospy.wait_for_service("set_nbv_hypotheses", 30)
    answer = rospy.ServiceProxy("set_nbv_hypotheses", SetNbvHypotheses)(clouds=[cloud])
    print("hypotheses:", answer.hypotheses, answer.message)
    current = RobotState(x=1.6, y=2.5, yaw=0.0, pan=0.0, tilt=-0.5)
    best = rospy.ServiceProxy("get_next_best_view", GetNextBestView)(current=current)
    print("found:", best.found, "types:", best.view.types, "rating: %.3f" % best.rating,
          "state:", best.view.state.x, best.view.state.y, best.view.state.yaw, best.message)
    # The view taken: what it saw turns from green to red on the markers.
    seen = rospy.ServiceProxy("update_nbv_hypotheses", UpdateNbvHypotheses)(
        camera=best.view.camera, types=best.view.types)
    print("deactivated normals:", seen.deactivated_normals)


if __name__ == "__main__":
    main()
