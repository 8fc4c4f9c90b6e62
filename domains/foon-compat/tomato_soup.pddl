; foon2pddl, encoding foon-compat, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-6ea87927)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    basil_fresh - object_node
    basil_on_tomato_soup - object_node
    bowl_contains_basil_tomato_soup - object_node
    bowl_contains_tomato_soup - object_node
    bowl_empty - object_node
    cutting_board_contains_onion - object_node
    cutting_board_contains_tomato - object_node
    cutting_board_empty - object_node
    immersion_blender_off - object_node
    immersion_blender_on - object_node
    knife - object_node
    ladle - object_node
    olive_oil_in_bottle - object_node
    olive_oil_in_pot - object_node
    onion_chopped_in_pot - object_node
    onion_chopped_on_cutting_board - object_node
    onion_in_pot_sauteed - object_node
    onion_on_cutting_board_peeled - object_node
    onion_on_cutting_board_whole - object_node
    onion_whole - object_node
    pot_contains_olive_oil_on_stove - object_node
    pot_contains_olive_oil_onion_on_stove - object_node
    pot_contains_olive_oil_onion_tomato_on_stove - object_node
    pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove - object_node
    pot_contains_tomato_soup_on_stove - object_node
    pot_empty - object_node
    pot_empty_on_stove - object_node
    stove_off - object_node
    stove_on - object_node
    tomato_chopped_in_pot - object_node
    tomato_chopped_on_cutting_board - object_node
    tomato_on_cutting_board_whole - object_node
    tomato_whole - object_node
    tomato_soup_chunky_in_pot - object_node
    tomato_soup_garnished_basil_in_bowl_pureed - object_node
    tomato_soup_in_bowl_pureed - object_node
    tomato_soup_in_pot_pureed - object_node
    vegetable_broth_in_carton - object_node
    vegetable_broth_in_pot - object_node
    wooden_spoon - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (is_available stove_off)
    )
    :effect (and
      (is_available stove_on)
    )
  )

  (:action functional_unit_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available onion_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available onion_on_cutting_board_whole)
    )
  )

  (:action functional_unit_48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
  )

  (:action functional_unit_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_chopped_on_cutting_board)
    )
  )

  (:action functional_unit_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available tomato_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available tomato_on_cutting_board_whole)
    )
  )

  (:action functional_unit_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_chopped_on_cutting_board)
    )
  )

  (:action functional_unit_52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters ()
    :precondition (and
      (is_available pot_empty)
      (is_available stove_off)
    )
    :effect (and
      (is_available pot_empty_on_stove)
    )
  )

  (:action functional_unit_53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters ()
    :precondition (and
      (is_available olive_oil_in_bottle)
      (is_available pot_empty_on_stove)
    )
    :effect (and
      (is_available olive_oil_in_pot)
      (is_available pot_contains_olive_oil_on_stove)
    )
  )

  (:action functional_unit_54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters ()
    :precondition (and
      (is_available onion_chopped_on_cutting_board)
      (is_available pot_contains_olive_oil_on_stove)
    )
    :effect (and
      (is_available onion_chopped_in_pot)
      (is_available pot_contains_olive_oil_onion_on_stove)
    )
  )

  (:action functional_unit_55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters ()
    :precondition (and
      (is_available olive_oil_in_pot)
      (is_available onion_chopped_in_pot)
      (is_available stove_on)
      (is_available wooden_spoon)
    )
    :effect (and
      (is_available onion_in_pot_sauteed)
      (is_available wooden_spoon)
    )
  )

  (:action functional_unit_56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters ()
    :precondition (and
      (is_available onion_in_pot_sauteed)
      (is_available pot_contains_olive_oil_onion_on_stove)
      (is_available tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is_available pot_contains_olive_oil_onion_tomato_on_stove)
      (is_available tomato_chopped_in_pot)
    )
  )

  (:action functional_unit_57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters ()
    :precondition (and
      (is_available pot_contains_olive_oil_onion_tomato_on_stove)
      (is_available vegetable_broth_in_carton)
    )
    :effect (and
      (is_available pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (is_available vegetable_broth_in_pot)
    )
  )

  (:action functional_unit_58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters ()
    :precondition (and
      (is_available olive_oil_in_pot)
      (is_available onion_in_pot_sauteed)
      (is_available pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (is_available stove_on)
      (is_available tomato_chopped_in_pot)
      (is_available vegetable_broth_in_pot)
    )
    :effect (and
      (is_available pot_contains_tomato_soup_on_stove)
      (is_available tomato_soup_chunky_in_pot)
    )
  )

  (:action functional_unit_59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters ()
    :precondition (and
      (is_available immersion_blender_off)
    )
    :effect (and
      (is_available immersion_blender_on)
    )
  )

  (:action functional_unit_60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters ()
    :precondition (and
      (is_available immersion_blender_on)
      (is_available pot_contains_tomato_soup_on_stove)
      (is_available tomato_soup_chunky_in_pot)
    )
    :effect (and
      (is_available immersion_blender_on)
      (is_available tomato_soup_in_pot_pureed)
    )
  )

  (:action functional_unit_61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available ladle)
      (is_available pot_contains_tomato_soup_on_stove)
      (is_available tomato_soup_in_pot_pureed)
    )
    :effect (and
      (is_available bowl_contains_tomato_soup)
      (is_available ladle)
      (is_available tomato_soup_in_bowl_pureed)
    )
  )

  (:action functional_unit_62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters ()
    :precondition (and
      (is_available basil_fresh)
      (is_available bowl_contains_tomato_soup)
      (is_available tomato_soup_in_bowl_pureed)
    )
    :effect (and
      (is_available basil_on_tomato_soup)
      (is_available bowl_contains_basil_tomato_soup)
      (is_available tomato_soup_garnished_basil_in_bowl_pureed)
    )
  )
)
