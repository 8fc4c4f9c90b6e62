; foon2pddl, encoding relational, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 30 (basil 1, bowl 1, cutting board 5, immersion blender 1, knife 1, ladle 1, olive oil 4, onion 3, pot 3, stove 2, tomato 2, tomato soup 2, vegetable broth 3, wooden spoon 1)
; objects: 5 x cutting board (empty): in the plan the counts are derived from (FOON's, unfolded), each of pick-and-place at 06-tomato_soup.foon:3 x3, pick-and-place at 06-tomato_soup.foon:42 x2 takes one out of that state and no unit puts one back
; objects: 3 x onion (whole): in the plan the counts are derived from (FOON's, unfolded), each of pick-and-place at 06-tomato_soup.foon:3 x3 takes one out of that state and no unit puts one back
; objects: 3 x pot (empty): in the plan the counts are derived from (FOON's, unfolded), each of pick-and-place at 06-tomato_soup.foon:67 x3 takes one out of that state and no unit puts one back
; objects: 2 x stove (off): in the plan the counts are derived from (FOON's, unfolded), each of turn on at 03-scrambled_eggs.foon:80 takes one out of that state and no unit puts one back; one stays for a unit that only reads it
; objects: 2 x tomato (whole): in the plan the counts are derived from (FOON's, unfolded), each of pick-and-place at 06-tomato_soup.foon:42 x2 takes one out of that state and no unit puts one back
; label mismatch: 06-tomato_soup.foon:212: bowl lists basil, which the unit puts on [tomato soup]
(define (problem make_tomato_soup)
  (:domain foon-relational-2483e756)
  (:objects
    basil_1 - basil
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    cutting_board_3 - cutting_board
    cutting_board_4 - cutting_board
    cutting_board_5 - cutting_board
    immersion_blender_1 - immersion_blender
    knife_1 - knife
    ladle_1 - ladle
    olive_oil_1 - olive_oil
    olive_oil_2 - olive_oil
    olive_oil_3 - olive_oil
    olive_oil_4 - olive_oil
    onion_1 - onion
    onion_2 - onion
    onion_3 - onion
    pot_1 - pot
    pot_2 - pot
    pot_3 - pot
    stove_1 - stove
    stove_2 - stove
    tomato_1 - tomato
    tomato_2 - tomato
    tomato_soup_1 - tomato_soup
    tomato_soup_2 - tomato_soup
    vegetable_broth_1 - vegetable_broth
    vegetable_broth_2 - vegetable_broth
    vegetable_broth_3 - vegetable_broth
    wooden_spoon_1 - wooden_spoon
    bottle_1 - bottle
    carton_1 - carton
  )
  (:init
    (in bottle_1 olive_oil_1)
    (in carton_1 vegetable_broth_1)
    (is basil_1 basil_fresh)
    (is bottle_1 bottle_contains_olive_oil)
    (is bowl_1 bowl_empty)
    (is carton_1 carton_contains_vegetable_broth)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is cutting_board_3 cutting_board_empty)
    (is cutting_board_4 cutting_board_empty)
    (is cutting_board_5 cutting_board_empty)
    (is immersion_blender_1 immersion_blender_off)
    (is knife_1 knife_plain)
    (is ladle_1 ladle_plain)
    (is olive_oil_1 olive_oil_in_bottle)
    (is olive_oil_2 not-yet-made)
    (is olive_oil_3 not-yet-made)
    (is olive_oil_4 not-yet-made)
    (is onion_1 onion_whole)
    (is onion_2 onion_whole)
    (is onion_3 onion_whole)
    (is pot_1 pot_empty)
    (is pot_2 pot_empty)
    (is pot_3 pot_empty)
    (is stove_1 stove_off)
    (is stove_2 stove_off)
    (is tomato_1 tomato_whole)
    (is tomato_2 tomato_whole)
    (is tomato_soup_1 not-yet-made)
    (is tomato_soup_2 not-yet-made)
    (is vegetable_broth_1 vegetable_broth_in_carton)
    (is vegetable_broth_2 not-yet-made)
    (is vegetable_broth_3 not-yet-made)
    (is wooden_spoon_1 wooden_spoon_plain)
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
