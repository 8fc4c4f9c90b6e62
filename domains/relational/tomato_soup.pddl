; foon2pddl, encoding relational, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (basil 1, bowl 1, cutting board 2, immersion blender 1, knife 1, ladle 1, olive oil 2, onion 1, pot 1, stove 1, tomato 1, tomato soup 1, vegetable broth 2, wooden spoon 1)
; objects: 2 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, and no unit puts one back
; label mismatch: 06-tomato_soup.foon:212: bowl lists basil, which the unit puts on [tomato soup]
(define (domain foon-relational-bdac14ca)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    basil - physical-object
    bottle - physical-object
    bowl - physical-object
    carton - physical-object
    cutting_board - physical-object
    immersion_blender - physical-object
    knife - physical-object
    ladle - physical-object
    olive_oil - physical-object
    onion - physical-object
    pot - physical-object
    stove - physical-object
    tomato - physical-object
    tomato_soup - physical-object
    vegetable_broth - physical-object
    wooden_spoon - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    basil_fresh - object-state
    basil_on_tomato_soup - object-state
    bottle_contains_olive_oil - object-state
    bowl_contains_basil_tomato_soup - object-state
    bowl_contains_tomato_soup - object-state
    bowl_empty - object-state
    carton_contains_vegetable_broth - object-state
    cutting_board_contains_onion - object-state
    cutting_board_contains_tomato - object-state
    cutting_board_empty - object-state
    immersion_blender_off - object-state
    immersion_blender_on - object-state
    knife_plain - object-state
    ladle_plain - object-state
    olive_oil_in_bottle - object-state
    olive_oil_in_pot - object-state
    onion_chopped_in_pot - object-state
    onion_chopped_on_cutting_board - object-state
    onion_in_pot_sauteed - object-state
    onion_on_cutting_board_peeled - object-state
    onion_on_cutting_board_whole - object-state
    onion_whole - object-state
    pot_contains_olive_oil_on_stove - object-state
    pot_contains_olive_oil_onion_on_stove - object-state
    pot_contains_olive_oil_onion_tomato_on_stove - object-state
    pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove - object-state
    pot_contains_tomato_soup_on_stove - object-state
    pot_empty - object-state
    pot_empty_on_stove - object-state
    stove_off - object-state
    stove_on - object-state
    tomato_chopped_in_pot - object-state
    tomato_chopped_on_cutting_board - object-state
    tomato_on_cutting_board_whole - object-state
    tomato_whole - object-state
    tomato_soup_chunky_in_pot - object-state
    tomato_soup_garnished_basil_in_bowl_pureed - object-state
    tomato_soup_in_bowl_pureed - object-state
    tomato_soup_in_pot_pureed - object-state
    vegetable_broth_in_carton - object-state
    vegetable_broth_in_pot - object-state
    wooden_spoon_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters (?stove - stove)
    :precondition (and
      (is ?stove stove_off)
    )
    :effect (and
      (is ?stove stove_on)
      (occupied stove_on)
      (not (is ?stove stove_off))
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?onion onion_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (on ?cutting_board ?onion)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?onion onion_whole))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (on ?cutting_board ?onion)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_on_cutting_board_peeled)
      (not (is ?onion onion_on_cutting_board_whole))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (on ?cutting_board ?onion)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_chopped_on_cutting_board)
      (not (is ?onion onion_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?tomato - tomato)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?tomato tomato_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (on ?cutting_board ?tomato)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?tomato tomato_whole))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?tomato - tomato)
    :precondition (and
      (is ?cutting_board cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (on ?cutting_board ?tomato)
      (occupied knife_plain)
    )
    :effect (and
      (is ?tomato tomato_chopped_on_cutting_board)
      (not (is ?tomato tomato_on_cutting_board_whole))
    )
  )

  (:action pick-and-place_u52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters (?pot - pot ?stove - stove)
    :precondition (and
      (is ?pot pot_empty)
      (is ?stove stove_off)
    )
    :effect (and
      (is ?pot pot_empty_on_stove)
      (on ?stove ?pot)
      (not (is ?pot pot_empty))
    )
  )

  (:action pour_u53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters (?pot - pot ?olive_oil_portion - olive_oil)
    :precondition (and
      (is ?pot pot_empty_on_stove)
      (is ?olive_oil_portion not-yet-made)
      (occupied olive_oil_in_bottle)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_on_stove)
      (is ?olive_oil_portion olive_oil_in_pot)
      (in ?pot ?olive_oil_portion)
      (not (is ?pot pot_empty_on_stove))
      (not (is ?olive_oil_portion not-yet-made))
    )
  )

  (:action pick-and-place_u54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters (?pot - pot ?onion - onion)
    :precondition (and
      (is ?pot pot_contains_olive_oil_on_stove)
      (is ?onion onion_chopped_on_cutting_board)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_on_stove)
      (is ?onion onion_chopped_in_pot)
      (in ?pot ?onion)
      (not (is ?pot pot_contains_olive_oil_on_stove))
      (not (is ?onion onion_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?onion) (not (on ?from_1 ?onion))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?onion) (is ?from_1 cutting_board_contains_onion)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_onion)))))
    )
  )

  (:action saute_u55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters (?olive_oil - olive_oil ?onion - onion)
    :precondition (and
      (occupied stove_on)
      (is ?olive_oil olive_oil_in_pot)
      (is ?onion onion_chopped_in_pot)
      (occupied wooden_spoon_plain)
    )
    :effect (and
      (is ?onion onion_in_pot_sauteed)
      (not (is ?onion onion_chopped_in_pot))
    )
  )

  (:action pick-and-place_u56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters (?pot - pot ?onion - onion ?tomato - tomato)
    :precondition (and
      (is ?pot pot_contains_olive_oil_onion_on_stove)
      (is ?onion onion_in_pot_sauteed)
      (in ?pot ?onion)
      (is ?tomato tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_tomato_on_stove)
      (is ?tomato tomato_chopped_in_pot)
      (in ?pot ?tomato)
      (not (is ?pot pot_contains_olive_oil_onion_on_stove))
      (not (is ?tomato tomato_chopped_on_cutting_board))
      (forall (?from_2 - physical-object) (when (on ?from_2 ?tomato) (not (on ?from_2 ?tomato))))
      (forall (?from_2 - physical-object) (when (and (on ?from_2 ?tomato) (is ?from_2 cutting_board_contains_tomato)) (and (is ?from_2 cutting_board_empty) (not (is ?from_2 cutting_board_contains_tomato)))))
    )
  )

  (:action pour_u57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters (?pot - pot ?vegetable_broth_portion - vegetable_broth)
    :precondition (and
      (is ?pot pot_contains_olive_oil_onion_tomato_on_stove)
      (is ?vegetable_broth_portion not-yet-made)
      (occupied vegetable_broth_in_carton)
    )
    :effect (and
      (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (is ?vegetable_broth_portion vegetable_broth_in_pot)
      (in ?pot ?vegetable_broth_portion)
      (not (is ?pot pot_contains_olive_oil_onion_tomato_on_stove))
      (not (is ?vegetable_broth_portion not-yet-made))
    )
  )

  (:action simmer_u58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters (?stove - stove ?pot - pot ?olive_oil - olive_oil ?onion - onion ?tomato - tomato ?vegetable_broth - vegetable_broth ?tomato_soup - tomato_soup)
    :precondition (and
      (is ?stove stove_on)
      (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove)
      (on ?stove ?pot)
      (is ?olive_oil olive_oil_in_pot)
      (in ?pot ?olive_oil)
      (is ?onion onion_in_pot_sauteed)
      (in ?pot ?onion)
      (is ?tomato tomato_chopped_in_pot)
      (in ?pot ?tomato)
      (is ?vegetable_broth vegetable_broth_in_pot)
      (in ?pot ?vegetable_broth)
      (is ?tomato_soup not-yet-made)
    )
    :effect (and
      (is ?pot pot_contains_tomato_soup_on_stove)
      (is ?olive_oil consumed)
      (is ?onion consumed)
      (is ?tomato consumed)
      (is ?vegetable_broth consumed)
      (is ?tomato_soup tomato_soup_chunky_in_pot)
      (in ?pot ?tomato_soup)
      (not (is ?pot pot_contains_olive_oil_onion_tomato_vegetable_broth_on_stove))
      (not (is ?olive_oil olive_oil_in_pot))
      (not (in ?pot ?olive_oil))
      (not (is ?onion onion_in_pot_sauteed))
      (not (in ?pot ?onion))
      (not (is ?tomato tomato_chopped_in_pot))
      (not (in ?pot ?tomato))
      (not (is ?vegetable_broth vegetable_broth_in_pot))
      (not (in ?pot ?vegetable_broth))
      (not (is ?tomato_soup not-yet-made))
      (forall (?olive_oil_alike - olive_oil) (when (and (in ?pot ?olive_oil_alike) (is ?olive_oil_alike olive_oil_in_pot)) (and (is ?olive_oil_alike consumed) (not (in ?pot ?olive_oil_alike)) (not (is ?olive_oil_alike olive_oil_in_pot)))))
      (forall (?onion_alike - onion) (when (and (in ?pot ?onion_alike) (is ?onion_alike onion_chopped_in_pot)) (and (is ?onion_alike consumed) (not (in ?pot ?onion_alike)) (not (is ?onion_alike onion_chopped_in_pot)))))
      (forall (?onion_alike-2 - onion) (when (and (in ?pot ?onion_alike-2) (is ?onion_alike-2 onion_in_pot_sauteed)) (and (is ?onion_alike-2 consumed) (not (in ?pot ?onion_alike-2)) (not (is ?onion_alike-2 onion_in_pot_sauteed)))))
      (forall (?tomato_alike - tomato) (when (and (in ?pot ?tomato_alike) (is ?tomato_alike tomato_chopped_in_pot)) (and (is ?tomato_alike consumed) (not (in ?pot ?tomato_alike)) (not (is ?tomato_alike tomato_chopped_in_pot)))))
      (forall (?vegetable_broth_alike - vegetable_broth) (when (and (in ?pot ?vegetable_broth_alike) (is ?vegetable_broth_alike vegetable_broth_in_pot)) (and (is ?vegetable_broth_alike consumed) (not (in ?pot ?vegetable_broth_alike)) (not (is ?vegetable_broth_alike vegetable_broth_in_pot)))))
    )
  )

  (:action turn_on_u59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters (?immersion_blender - immersion_blender)
    :precondition (and
      (is ?immersion_blender immersion_blender_off)
    )
    :effect (and
      (is ?immersion_blender immersion_blender_on)
      (occupied immersion_blender_on)
      (not (is ?immersion_blender immersion_blender_off))
    )
  )

  (:action blend_u60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters (?pot - pot ?tomato_soup - tomato_soup)
    :precondition (and
      (occupied immersion_blender_on)
      (is ?pot pot_contains_tomato_soup_on_stove)
      (is ?tomato_soup tomato_soup_chunky_in_pot)
      (in ?pot ?tomato_soup)
    )
    :effect (and
      (is ?tomato_soup tomato_soup_in_pot_pureed)
      (not (is ?tomato_soup tomato_soup_chunky_in_pot))
    )
  )

  (:action scoop_u61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters (?pot - pot ?tomato_soup - tomato_soup ?bowl - bowl)
    :precondition (and
      (is ?pot pot_contains_tomato_soup_on_stove)
      (is ?tomato_soup tomato_soup_in_pot_pureed)
      (in ?pot ?tomato_soup)
      (occupied ladle_plain)
      (is ?bowl bowl_empty)
    )
    :effect (and
      (is ?pot pot_empty_on_stove)
      (is ?tomato_soup tomato_soup_in_bowl_pureed)
      (in ?bowl ?tomato_soup)
      (is ?bowl bowl_contains_tomato_soup)
      (not (is ?pot pot_contains_tomato_soup_on_stove))
      (not (is ?tomato_soup tomato_soup_in_pot_pureed))
      (not (in ?pot ?tomato_soup))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action sprinkle_u62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters (?bowl - bowl ?tomato_soup - tomato_soup ?basil - basil)
    :precondition (and
      (is ?bowl bowl_contains_tomato_soup)
      (is ?tomato_soup tomato_soup_in_bowl_pureed)
      (in ?bowl ?tomato_soup)
      (is ?basil basil_fresh)
    )
    :effect (and
      (is ?bowl bowl_contains_basil_tomato_soup)
      (occupied bowl_contains_basil_tomato_soup)
      (is ?tomato_soup tomato_soup_garnished_basil_in_bowl_pureed)
      (occupied tomato_soup_garnished_basil_in_bowl_pureed)
      (is ?basil basil_on_tomato_soup)
      (occupied basil_on_tomato_soup)
      (on ?tomato_soup ?basil)
      (not (is ?bowl bowl_contains_tomato_soup))
      (not (is ?tomato_soup tomato_soup_in_bowl_pureed))
      (not (is ?basil basil_fresh))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: tomato soup (garnished {basil}, in [bowl], pureed)
    :parameters ()
    :precondition (and
      (occupied tomato_soup_garnished_basil_in_bowl_pureed)
    )
    :effect (and
      (goal-reached)
    )
  )
)
