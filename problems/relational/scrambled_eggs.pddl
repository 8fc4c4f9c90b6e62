; foon2pddl, encoding relational, level 3: 14 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 15 (black pepper 1, bowl 1, butter 1, egg 1, egg mixture 1, fork 1, frying pan 1, milk 2, plate 1, salt 1, scrambled eggs 1, spatula 1, stove 1, whisk 1)
(define (problem make_scrambled_eggs)
  (:domain foon-relational-4ab76182)
  (:objects
    black_pepper_1 - black_pepper
    bowl_1 - bowl
    butter_1 - butter
    egg_1 - egg
    egg_mixture_1 - egg_mixture
    frying_pan_1 - frying_pan
    milk_2 - milk
    plate_1 - plate
    salt_1 - salt
    scrambled_eggs_1 - scrambled_eggs
    stove_1 - stove
  )
  (:init
    (is black_pepper_1 black_pepper_ground)
    (is bowl_1 bowl_empty)
    (is butter_1 butter_solid)
    (is egg_1 egg_whole)
    (is egg_mixture_1 not-yet-made)
    (is frying_pan_1 frying_pan_empty)
    (is milk_2 not-yet-made)
    (is plate_1 plate_empty)
    (is salt_1 salt_granulated)
    (is scrambled_eggs_1 not-yet-made)
    (is stove_1 stove_off)
    (occupied carton_contains_milk)
    (occupied fork_plain)
    (occupied milk_in_carton)
    (occupied spatula_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
