; foon2pddl, encoding tree, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-4f6538c2)
  (:requirements :strips)
  (:predicates
    (basil_fresh)  ; basil (fresh)
    (basil_on_tomato_soup)  ; basil (on [tomato soup])
    (bowl_contains_basil_tomato_soup)  ; bowl (contains {basil, tomato soup})
    (bowl_contains_tomato_soup)  ; bowl (contains {tomato soup})
    (bowl_empty)  ; bowl (empty)
    (cutting_board_contains_onion)  ; cutting board (contains {onion})
    (cutting_board_contains_tomato)  ; cutting board (contains {tomato})
    (cutting_board_empty)  ; cutting board (empty)
    (immersion_blender_off)  ; immersion blender (off)
    (immersion_blender_on)  ; immersion blender (on)
    (knife)  ; knife
    (ladle)  ; ladle
    (olive_oil_in_bottle)  ; olive oil (in [bottle])
    (olive_oil_in_pot)  ; olive oil (in [pot])
    (onion_chopped_in_pot)  ; onion (chopped, in [pot])
    (onion_chopped_on_cutting_board)  ; onion (chopped, on [cutting board])
    (onion_in_pot_sauteed)  ; onion (in [pot], sauteed)
    (onion_on_cutting_board_peeled)  ; onion (on [cutting board], peeled)
    (onion_on_cutting_board_whole)  ; onion (on [cutting board], whole)
    (onion_whole)  ; onion (whole)
    (pot_contains_olive_oil_on_stove)  ; pot (contains {olive oil}, on [stove])
    (pot_contains_olive_oil_onion_on_stove)  ; pot (contains {olive oil, onion}, on [stove])
    (pot_contains_olive_oil_onion_tomato_on_stove)  ; pot (contains {olive oil, onion, tomato}, on [stove])
    (pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)  ; pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove])
    (pot_contains_tomato_soup_on_stove)  ; pot (contains {tomato soup}, on [stove])
    (pot_empty)  ; pot (empty)
    (pot_empty_on_stove)  ; pot (empty, on [stove])
    (stove_off)  ; stove (off)
    (stove_on)  ; stove (on)
    (tomato_chopped_in_pot)  ; tomato (chopped, in [pot])
    (tomato_chopped_on_cutting_board)  ; tomato (chopped, on [cutting board])
    (tomato_on_cutting_board_whole)  ; tomato (on [cutting board], whole)
    (tomato_whole)  ; tomato (whole)
    (tomato_soup_chunky_in_pot)  ; tomato soup (chunky, in [pot])
    (tomato_soup_garnished_basil_in_bowl_pureed)  ; tomato soup (garnished {basil}, in [bowl], pureed)
    (tomato_soup_in_bowl_pureed)  ; tomato soup (in [bowl], pureed)
    (tomato_soup_in_pot_pureed)  ; tomato soup (in [pot], pureed)
    (vegetable_broth_in_carton)  ; vegetable broth (in [carton])
    (vegetable_broth_in_pot)  ; vegetable broth (in [pot])
    (wooden_spoon)  ; wooden spoon
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (stove_off)
    )
    :effect (and
      (stove_on)
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (onion_whole)
    )
    :effect (and
      (cutting_board_contains_onion)
      (onion_on_cutting_board_whole)
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_peeled)
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_peeled)
    )
    :effect (and
      (cutting_board_contains_onion)
      (knife)
      (onion_chopped_on_cutting_board)
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (tomato_whole)
    )
    :effect (and
      (cutting_board_contains_tomato)
      (tomato_on_cutting_board_whole)
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_tomato)
      (knife)
      (tomato_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_tomato)
      (knife)
      (tomato_chopped_on_cutting_board)
    )
  )

  (:action pick-and-place_u52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters ()
    :precondition (and
      (pot_empty)
      (stove_off)
    )
    :effect (and
      (pot_empty_on_stove)
    )
  )

  (:action pour_u53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters ()
    :precondition (and
      (olive_oil_in_bottle)
      (pot_empty_on_stove)
    )
    :effect (and
      (olive_oil_in_pot)
      (pot_contains_olive_oil_on_stove)
    )
  )

  (:action pick-and-place_u54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters ()
    :precondition (and
      (onion_chopped_on_cutting_board)
      (pot_contains_olive_oil_on_stove)
    )
    :effect (and
      (onion_chopped_in_pot)
      (pot_contains_olive_oil_onion_on_stove)
    )
  )

  (:action saute_u55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters ()
    :precondition (and
      (olive_oil_in_pot)
      (onion_chopped_in_pot)
      (stove_on)
      (wooden_spoon)
    )
    :effect (and
      (onion_in_pot_sauteed)
      (wooden_spoon)
    )
  )

  (:action pick-and-place_u56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters ()
    :precondition (and
      (onion_in_pot_sauteed)
      (pot_contains_olive_oil_onion_on_stove)
      (tomato_chopped_on_cutting_board)
    )
    :effect (and
      (pot_contains_olive_oil_onion_tomato_on_stove)
      (tomato_chopped_in_pot)
    )
  )

  (:action pour_u57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters ()
    :precondition (and
      (pot_contains_olive_oil_onion_tomato_on_stove)
      (vegetable_broth_in_carton)
    )
    :effect (and
      (pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (vegetable_broth_in_pot)
    )
  )

  (:action simmer_u58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters ()
    :precondition (and
      (olive_oil_in_pot)
      (onion_in_pot_sauteed)
      (pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (stove_on)
      (tomato_chopped_in_pot)
      (vegetable_broth_in_pot)
    )
    :effect (and
      (pot_contains_tomato_soup_on_stove)
      (tomato_soup_chunky_in_pot)
    )
  )

  (:action turn_on_u59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters ()
    :precondition (and
      (immersion_blender_off)
    )
    :effect (and
      (immersion_blender_on)
    )
  )

  (:action blend_u60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters ()
    :precondition (and
      (immersion_blender_on)
      (pot_contains_tomato_soup_on_stove)
      (tomato_soup_chunky_in_pot)
    )
    :effect (and
      (immersion_blender_on)
      (tomato_soup_in_pot_pureed)
    )
  )

  (:action scoop_u61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters ()
    :precondition (and
      (bowl_empty)
      (ladle)
      (pot_contains_tomato_soup_on_stove)
      (tomato_soup_in_pot_pureed)
    )
    :effect (and
      (bowl_contains_tomato_soup)
      (ladle)
      (tomato_soup_in_bowl_pureed)
    )
  )

  (:action sprinkle_u62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters ()
    :precondition (and
      (basil_fresh)
      (bowl_contains_tomato_soup)
      (tomato_soup_in_bowl_pureed)
    )
    :effect (and
      (basil_on_tomato_soup)
      (bowl_contains_basil_tomato_soup)
      (tomato_soup_garnished_basil_in_bowl_pureed)
    )
  )
)
