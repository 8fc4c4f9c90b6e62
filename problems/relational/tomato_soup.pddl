; foon2pddl, encoding relational, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (basil 1, bowl 1, cutting board 2, immersion blender 1, knife 1, ladle 1, olive oil 2, onion 1, pot 1, stove 1, tomato 1, tomato soup 1, vegetable broth 2, wooden spoon 1)
; objects: 2 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, and no unit puts one back
; label mismatch: 06-tomato_soup.foon:212: bowl lists basil, which the unit puts on [tomato soup]
(define (problem make_tomato_soup)
  (:domain foon-relational-bdac14ca)
  (:objects
    basil_1 - basil
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    immersion_blender_1 - immersion_blender
    olive_oil_2 - olive_oil
    onion_1 - onion
    pot_1 - pot
    stove_1 - stove
    tomato_1 - tomato
    tomato_soup_1 - tomato_soup
    vegetable_broth_2 - vegetable_broth
  )
  (:init
    (is basil_1 basil_fresh)
    (is bowl_1 bowl_empty)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is immersion_blender_1 immersion_blender_off)
    (is olive_oil_2 not-yet-made)
    (is onion_1 onion_whole)
    (is pot_1 pot_empty)
    (is stove_1 stove_off)
    (is tomato_1 tomato_whole)
    (is tomato_soup_1 not-yet-made)
    (is vegetable_broth_2 not-yet-made)
    (occupied bottle_contains_olive_oil)
    (occupied carton_contains_vegetable_broth)
    (occupied knife_plain)
    (occupied ladle_plain)
    (occupied olive_oil_in_bottle)
    (occupied vegetable_broth_in_carton)
    (occupied wooden_spoon_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
