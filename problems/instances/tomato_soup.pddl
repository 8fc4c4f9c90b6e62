; foon2pddl, encoding instances, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 16 (basil 1, bowl 1, cutting board 2, immersion blender 1, knife 1, ladle 1, olive oil 1, onion 1, pot 1, stove 2, tomato 1, tomato soup 1, vegetable broth 1, wooden spoon 1)
(define (problem make_tomato_soup)
  (:domain foon-instances-4c2425ee)
  (:objects
    basil_1 - basil
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    immersion_blender_1 - immersion_blender
    knife_1 - knife
    ladle_1 - ladle
    olive_oil_1 - olive_oil
    onion_1 - onion
    pot_1 - pot
    stove_1 - stove
    stove_2 - stove
    tomato_1 - tomato
    tomato_soup_1 - tomato_soup
    vegetable_broth_1 - vegetable_broth
    wooden_spoon_1 - wooden_spoon
  )
  (:init
    (is basil_1 basil_fresh)
    (is bowl_1 bowl_empty)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is immersion_blender_1 immersion_blender_off)
    (is knife_1 knife_plain)
    (is ladle_1 ladle_plain)
    (is olive_oil_1 olive_oil_in_bottle)
    (is onion_1 onion_whole)
    (is pot_1 pot_empty)
    (is stove_1 stove_off)
    (is stove_2 stove_off)
    (is tomato_1 tomato_whole)
    (is tomato_soup_1 not-yet-made)
    (is vegetable_broth_1 vegetable_broth_in_carton)
    (is wooden_spoon_1 wooden_spoon_plain)
    (occupied knife_plain)
    (occupied ladle_plain)
    (occupied wooden_spoon_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
