; foon2pddl, encoding instances, level 3: 15 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 18 (baking powder 1, butter 1, egg 1, flour 1, frying pan 1, ladle 1, maple syrup 1, milk 1, mixing bowl 1, pancake 1, pancake batter 1, plate 1, salt 1, spatula 1, stove 2, sugar 1, whisk 1)
(define (problem make_pancake)
  (:domain foon-instances-5358e0c9)
  (:objects
    baking_powder_1 - baking_powder
    butter_1 - butter
    egg_1 - egg
    flour_1 - flour
    frying_pan_1 - frying_pan
    ladle_1 - ladle
    maple_syrup_1 - maple_syrup
    milk_1 - milk
    mixing_bowl_1 - mixing_bowl
    pancake_1 - pancake
    pancake_batter_1 - pancake_batter
    plate_1 - plate
    salt_1 - salt
    spatula_1 - spatula
    stove_1 - stove
    stove_2 - stove
    sugar_1 - sugar
    whisk_1 - whisk
  )
  (:init
    (is baking_powder_1 baking_powder_powder)
    (is butter_1 butter_solid)
    (is egg_1 egg_whole)
    (is flour_1 flour_powder)
    (is frying_pan_1 frying_pan_empty)
    (is ladle_1 ladle_plain)
    (is maple_syrup_1 maple_syrup_in_bottle)
    (is milk_1 milk_in_carton)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is pancake_1 not-yet-made)
    (is pancake_batter_1 not-yet-made)
    (is plate_1 plate_empty)
    (is salt_1 salt_granulated)
    (is spatula_1 spatula_plain)
    (is stove_1 stove_off)
    (is stove_2 stove_off)
    (is sugar_1 sugar_granulated)
    (is whisk_1 whisk_plain)
    (occupied ladle_plain)
    (occupied spatula_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
