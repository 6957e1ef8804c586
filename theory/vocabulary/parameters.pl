% The 30 scene parameters of a pour.
%
% Read by SWI-Prolog and by clingo alike: ground facts with atoms, integers
% and quoted text only. Units are integers (mm, deg, ms, g, mg, permille,
% count) so that no float appears.
%
% parameter(Name, Group, Unit, Low, High): the parameter's bounds.
% prior(Name, uniform(Low, High)): the distribution of a parameter that no
%   proposition of an antecedent draws: uniform over [Low, High], within the
%   bounds. The priors are the one meaning of what a question leaves
%   unsaid: the ordinary pour, what a person means by "pour" when they say
%   nothing more. The source starts and ends upright and level, beside and
%   above the destination, in line with it; when pouring it is tilted past
%   the horizontal so that the liquid pours (100 to 140 degrees), over or
%   near the destination (its base 0 to 80 mm from the destination's axis),
%   a little above the rim (50 to 120 mm), level and in line. It moves at a
%   moderate speed, and the bodies and the liquid are ordinary: every
%   material and the amount lie between the values that a proposition
%   names as extreme (between a light and a heavy liquid, a slippery and a
%   grippy bowl, a little and a full source), so that each extreme a
%   person names is a departure from the ordinary pour, not a part of it.
% parameter_gloss(Name, Text).
%
% Frame: positions are those of the centre of the source bowl's base,
% relative to the centre of the destination bowl's rim (x points from the
% destination towards where the source comes from, z up). Orientation is
% roll (about x), pitch (about y: positive tips the source's lip towards -x,
% that is towards the destination) and yaw (about z), in degrees.

parameter(start_x, start_pose, mm, -250, 250).
parameter(start_y, start_pose, mm, -150, 150).
parameter(start_z, start_pose, mm, -40, 400).
parameter(start_roll, start_pose, deg, -30, 30).
parameter(start_pitch, start_pose, deg, -30, 40).
parameter(start_yaw, start_pose, deg, -180, 180).
parameter(pour_x, pour_pose, mm, -250, 250).
parameter(pour_y, pour_pose, mm, -150, 150).
parameter(pour_z, pour_pose, mm, -40, 400).
parameter(pour_roll, pour_pose, deg, -30, 30).
parameter(pour_pitch, pour_pose, deg, -30, 180).
parameter(pour_yaw, pour_pose, deg, -180, 180).
parameter(end_x, end_pose, mm, -250, 250).
parameter(end_y, end_pose, mm, -150, 150).
parameter(end_z, end_pose, mm, -40, 400).
parameter(end_roll, end_pose, deg, -30, 30).
parameter(end_pitch, end_pose, deg, -30, 180).
parameter(end_yaw, end_pose, deg, -180, 180).
parameter(approach_duration, motion, ms, 300, 4000).
parameter(retreat_duration, motion, ms, 300, 4000).
parameter(source_mass, source, g, 100, 2000).
parameter(source_restitution, source, permille, 0, 950).
parameter(source_friction, source, permille, 0, 1500).
parameter(destination_mass, destination, g, 20, 3000).
parameter(destination_restitution, destination, permille, 0, 950).
parameter(destination_friction, destination, permille, 0, 1500).
parameter(particle_mass, liquid, mg, 100, 10000).
parameter(particle_restitution, liquid, permille, 0, 950).
parameter(particle_friction, liquid, permille, 0, 1500).
parameter(particle_count, liquid, count, 10, 200).

prior(start_x, uniform(100, 250)).
prior(start_y, uniform(-20, 20)).
prior(start_z, uniform(100, 300)).
prior(start_roll, uniform(-5, 5)).
prior(start_pitch, uniform(-5, 5)).
prior(start_yaw, uniform(-180, 180)).
prior(pour_x, uniform(0, 80)).
prior(pour_y, uniform(-20, 20)).
prior(pour_z, uniform(50, 120)).
prior(pour_roll, uniform(-5, 5)).
prior(pour_pitch, uniform(100, 140)).
prior(pour_yaw, uniform(-180, 180)).
prior(end_x, uniform(100, 250)).
prior(end_y, uniform(-20, 20)).
prior(end_z, uniform(100, 300)).
prior(end_roll, uniform(-5, 5)).
prior(end_pitch, uniform(-5, 5)).
prior(end_yaw, uniform(-180, 180)).
prior(approach_duration, uniform(1000, 2000)).
prior(retreat_duration, uniform(1000, 2000)).
prior(source_mass, uniform(400, 800)).
prior(source_restitution, uniform(150, 600)).
prior(source_friction, uniform(200, 800)).
prior(destination_mass, uniform(200, 600)).
prior(destination_restitution, uniform(150, 600)).
prior(destination_friction, uniform(200, 800)).
prior(particle_mass, uniform(1500, 3000)).
prior(particle_restitution, uniform(150, 600)).
prior(particle_friction, uniform(200, 800)).
prior(particle_count, uniform(40, 140)).

parameter_gloss(start_x, "distance of the source from the destination's axis, towards the side it comes from, at the start").
parameter_gloss(start_y, "sideways offset of the source at the start").
parameter_gloss(start_z, "height of the source's base above the destination's rim at the start").
parameter_gloss(start_roll, "sideways roll of the source at the start").
parameter_gloss(start_pitch, "tilt of the source towards the destination at the start").
parameter_gloss(start_yaw, "turn of the source about the vertical at the start").
parameter_gloss(pour_x, "distance of the source from the destination's axis when pouring").
parameter_gloss(pour_y, "sideways offset of the source when pouring").
parameter_gloss(pour_z, "height of the source's base above the destination's rim when pouring").
parameter_gloss(pour_roll, "sideways roll of the source when pouring").
parameter_gloss(pour_pitch, "tilt of the source towards the destination when pouring").
parameter_gloss(pour_yaw, "turn of the source about the vertical when pouring").
parameter_gloss(end_x, "distance of the source from the destination's axis at the end").
parameter_gloss(end_y, "sideways offset of the source at the end").
parameter_gloss(end_z, "height of the source's base above the destination's rim at the end").
parameter_gloss(end_roll, "sideways roll of the source at the end").
parameter_gloss(end_pitch, "tilt of the source towards the destination at the end").
parameter_gloss(end_yaw, "turn of the source about the vertical at the end").
parameter_gloss(approach_duration, "time to move the source from the start pose to the pouring pose").
parameter_gloss(retreat_duration, "time to move the source from the pouring pose to the end pose").
parameter_gloss(source_mass, "mass of the source bowl").
parameter_gloss(source_restitution, "bounciness of the source bowl").
parameter_gloss(source_friction, "friction of the source bowl").
parameter_gloss(destination_mass, "mass of the destination bowl").
parameter_gloss(destination_restitution, "bounciness of the destination bowl").
parameter_gloss(destination_friction, "friction of the destination bowl").
parameter_gloss(particle_mass, "mass of one particle of liquid").
parameter_gloss(particle_restitution, "bounciness of the liquid's particles").
parameter_gloss(particle_friction, "friction of the liquid's particles").
parameter_gloss(particle_count, "number of particles of liquid").

% scene(Constant, Unit, Value): the fixed geometry of the scene.
scene(destination_radius, mm, 70).
scene(destination_height, mm, 60).
scene(source_radius, mm, 45).
scene(source_height, mm, 45).
scene(wall_thickness, mm, 4).
scene(particle_radius, mm, 5).
