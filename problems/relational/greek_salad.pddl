; foon2pddl, encoding relational, level 3: 18 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (black olive 1, bowl 1, cucumber 1, cutting board 3, feta cheese 1, greek salad 1, knife 1, olive oil 2, onion 1, oregano 1, red wine vinegar 2, salad tongs 1, tomato 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 08-greek_salad.foon:3, and no unit puts one back
(define (problem make_greek_salad)
  (:domain foon-relational-61817839)
  (:objects
    black_olive_1 - black_olive
    bowl_1 - bowl
    cucumber_1 - cucumber
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    cutting_board_3 - cutting_board
    feta_cheese_1 - feta_cheese
    greek_salad_1 - greek_salad
    olive_oil_2 - olive_oil
    onion_1 - onion
    oregano_1 - oregano
    red_wine_vinegar_2 - red_wine_vinegar
    tomato_1 - tomato
  )
  (:init
    (is black_olive_1 black_olive_pitted)
    (is bowl_1 bowl_empty)
    (is cucumber_1 cucumber_whole)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is cutting_board_3 cutting_board_empty)
    (is feta_cheese_1 feta_cheese_crumbled)
    (is greek_salad_1 not-yet-made)
    (is olive_oil_2 not-yet-made)
    (is onion_1 onion_whole)
    (is oregano_1 oregano_dried)
    (is red_wine_vinegar_2 not-yet-made)
    (is tomato_1 tomato_whole)
    (occupied bottle_contains_olive_oil_red_wine_vinegar)
    (occupied knife_plain)
    (occupied olive_oil_in_bottle)
    (occupied red_wine_vinegar_in_bottle)
    (occupied salad_tongs_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
