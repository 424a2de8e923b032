// A humanoid-sized tree for the compile-fail tests whose point is the length of the compiler's
// output: 25 bodies on a floating base (legs of six joints, a torso of two, arms of four, a
// neck of two: nq = 32, nv = 30) and 50 named frames, so that every line that prints the tree's
// type is long and an instantiation trace runs to kilobytes.
#pragma once

#include <ctga/chains/tree.hpp>

namespace large_tree_fixture {
namespace ch = ctga::chains;
using humanoid = ch::tree<
    ch::link<-1, ch::floating>,  // 0 pelvis
    ch::link<0, ch::revolute_z>,  // 1 l_hip_yaw
    ch::link<1, ch::revolute_x>,  // 2 l_hip_roll
    ch::link<2, ch::revolute_y>,  // 3 l_hip_pitch
    ch::link<3, ch::revolute_y>,  // 4 l_knee
    ch::link<4, ch::revolute_y>,  // 5 l_ankle_pitch
    ch::link<5, ch::revolute_x>,  // 6 l_ankle_roll
    ch::link<0, ch::revolute_z>,  // 7 r_hip_yaw
    ch::link<7, ch::revolute_x>,  // 8 r_hip_roll
    ch::link<8, ch::revolute_y>,  // 9 r_hip_pitch
    ch::link<9, ch::revolute_y>,  // 10 r_knee
    ch::link<10, ch::revolute_y>,  // 11 r_ankle_pitch
    ch::link<11, ch::revolute_x>,  // 12 r_ankle_roll
    ch::link<0, ch::revolute_z>,  // 13 torso_yaw
    ch::link<13, ch::revolute_y>,  // 14 torso_pitch
    ch::link<14, ch::revolute_y>,  // 15 l_shoulder_pitch
    ch::link<15, ch::revolute_x>,  // 16 l_shoulder_roll
    ch::link<16, ch::revolute_z>,  // 17 l_shoulder_yaw
    ch::link<17, ch::revolute_y>,  // 18 l_elbow
    ch::link<14, ch::revolute_y>,  // 19 r_shoulder_pitch
    ch::link<19, ch::revolute_x>,  // 20 r_shoulder_roll
    ch::link<20, ch::revolute_z>,  // 21 r_shoulder_yaw
    ch::link<21, ch::revolute_y>,  // 22 r_elbow
    ch::link<14, ch::revolute_z>,  // 23 neck_yaw
    ch::link<23, ch::revolute_y>,  // 24 neck_pitch
    ch::fixed_frame<"pelvis_link", 0>,
    ch::fixed_frame<"l_hip_yaw_link", 1>,
    ch::fixed_frame<"l_hip_roll_link", 2>,
    ch::fixed_frame<"l_hip_pitch_link", 3>,
    ch::fixed_frame<"l_knee_link", 4>,
    ch::fixed_frame<"l_ankle_pitch_link", 5>,
    ch::fixed_frame<"l_ankle_roll_link", 6>,
    ch::fixed_frame<"r_hip_yaw_link", 7>,
    ch::fixed_frame<"r_hip_roll_link", 8>,
    ch::fixed_frame<"r_hip_pitch_link", 9>,
    ch::fixed_frame<"r_knee_link", 10>,
    ch::fixed_frame<"r_ankle_pitch_link", 11>,
    ch::fixed_frame<"r_ankle_roll_link", 12>,
    ch::fixed_frame<"torso_yaw_link", 13>,
    ch::fixed_frame<"torso_pitch_link", 14>,
    ch::fixed_frame<"l_shoulder_pitch_link", 15>,
    ch::fixed_frame<"l_shoulder_roll_link", 16>,
    ch::fixed_frame<"l_shoulder_yaw_link", 17>,
    ch::fixed_frame<"l_elbow_link", 18>,
    ch::fixed_frame<"r_shoulder_pitch_link", 19>,
    ch::fixed_frame<"r_shoulder_roll_link", 20>,
    ch::fixed_frame<"r_shoulder_yaw_link", 21>,
    ch::fixed_frame<"r_elbow_link", 22>,
    ch::fixed_frame<"neck_yaw_link", 23>,
    ch::fixed_frame<"neck_pitch_link", 24>,
    ch::fixed_frame<"base_link", 0>,
    ch::fixed_frame<"imu", 0>,
    ch::fixed_frame<"l_foot", 6>,
    ch::fixed_frame<"l_sole", 6>,
    ch::fixed_frame<"l_toe", 6>,
    ch::fixed_frame<"l_heel", 6>,
    ch::fixed_frame<"r_foot", 12>,
    ch::fixed_frame<"r_sole", 12>,
    ch::fixed_frame<"r_toe", 12>,
    ch::fixed_frame<"r_heel", 12>,
    ch::fixed_frame<"chest", 14>,
    ch::fixed_frame<"lidar", 14>,
    ch::fixed_frame<"l_hand", 18>,
    ch::fixed_frame<"l_palm", 18>,
    ch::fixed_frame<"tool0", 18>,
    ch::fixed_frame<"r_hand", 22>,
    ch::fixed_frame<"r_palm", 22>,
    ch::fixed_frame<"tool1", 22>,
    ch::fixed_frame<"head", 24>,
    ch::fixed_frame<"camera_left", 24>,
    ch::fixed_frame<"camera_right", 24>,
    ch::fixed_frame<"camera_depth", 24>,
    ch::fixed_frame<"microphone", 24>,
    ch::fixed_frame<"world_marker", -1>,
    ch::fixed_frame<"charging_port", 0>
>;
}  // namespace large_tree_fixture
