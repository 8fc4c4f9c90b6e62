; foon2pddl, encoding instances, level 3: 30 of 101 units after relevance pruning
; goal: scrambled eggs (2 candidate nodes)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 24 (avocado 1, black pepper 1, bowl 1, butter 1, cilantro 1, cutting board 1, egg 1, egg mixture 1, fork 1, frying pan 1, juicer 1, knife 1, lime 1, milk 1, onion 1, plate 1, salt 1, scrambled eggs 1, spatula 1, spoon 1, stove 2, tomato 1, whisk 1)
(define (problem make_scrambled_eggs)
  (:domain foon-instances)
  (:objects
    avocado_1 - avocado
    black_pepper_1 - black_pepper
    bowl_1 - bowl
    butter_1 - butter
    cilantro_1 - cilantro
    cutting_board_1 - cutting_board
    egg_1 - egg
    egg_mixture_1 - egg_mixture
    fork_1 - fork
    frying_pan_1 - frying_pan
    juicer_1 - juicer
    knife_1 - knife
    lime_1 - lime
    milk_1 - milk
    onion_1 - onion
    plate_1 - plate
    salt_1 - salt
    scrambled_eggs_1 - scrambled_eggs
    spatula_1 - spatula
    spoon_1 - spoon
    stove_1 - stove
    stove_2 - stove
    tomato_1 - tomato
    whisk_1 - whisk
  )
  (:init
    (is avocado_1 avocado_whole)
    (is black_pepper_1 black_pepper_ground)
    (is bowl_1 bowl_empty)
    (is butter_1 butter_solid)
    (is cilantro_1 cilantro_fresh)
    (is cutting_board_1 cutting_board_empty)
    (is egg_1 egg_whole)
    (is egg_mixture_1 not-yet-made)
    (is fork_1 fork_plain)
    (is frying_pan_1 frying_pan_empty)
    (is juicer_1 juicer_empty)
    (is knife_1 knife_plain)
    (is lime_1 lime_whole)
    (is milk_1 milk_in_carton)
    (is onion_1 onion_whole)
    (is plate_1 plate_empty)
    (is salt_1 salt_granulated)
    (is scrambled_eggs_1 not-yet-made)
    (is spatula_1 spatula_plain)
    (is spoon_1 spoon_plain)
    (is stove_1 stove_off)
    (is stove_2 stove_off)
    (is tomato_1 tomato_whole)
    (is whisk_1 whisk_plain)
    (occupied fork_plain)
    (occupied juicer_empty)
    (occupied knife_plain)
    (occupied spatula_plain)
    (occupied spoon_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
