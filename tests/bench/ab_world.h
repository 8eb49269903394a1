/* ab_world.h - one build of ga2d_physics.h as ab_steps.c sees it.

   ab_world.c is compiled twice by ab_header.sh, each time against another
   copy of the header (-I its folder) with -DAB_SIDE=old or new and
   GA2D_STATIC, so the two builds' library functions stay private to their
   units and one program can step a world of each in turn.  Per build:
     holds   whether make can build the named scene: 1 for a fixed list
             of bodies, 0 for a scene whose bodies come and go or that
             has a chain (rain, mixed_pile, spinner: ab_steps skips it,
             saying so; the runs measure covers it), -1 for an unknown one;
     make    the named box scene of scenes.h (no bodies that come and go)
             in a world at the defaults with the scene's gravity and sleep
             switch; NULL for an unknown scene or a refused body;
     steps   the scene's step count;
     step    sets the tumbler's wall velocities (untimed), then one
             ga2d_world_step, timed: its ms, or -1 if it failed;
     figure  the scene's accuracy figure so far (scenes.h: drift of the
             probe, momentum error, or the deepest penetration seen);
     figure_name  its name;
     free    destroys it. */
#ifndef GA2D_AB_WORLD_H
#define GA2D_AB_WORLD_H

typedef struct ab_world ab_world;

#define AB_WORLD_FUNCTIONS(P)                                                                                    \
    int P##holds(const char *scene);                                                                             \
    ab_world *P##make(const char *scene);                                                                        \
    int P##steps(const ab_world *a);                                                                             \
    double P##step(ab_world *a);                                                                                 \
    double P##figure(const ab_world *a);                                                                         \
    const char *P##figure_name(const ab_world *a);                                                               \
    void P##free(ab_world *a);

AB_WORLD_FUNCTIONS(ab_old_)
AB_WORLD_FUNCTIONS(ab_new_)

#endif
