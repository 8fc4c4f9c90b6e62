; foon2pddl, encoding relational, level 3: 18 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (black olive 1, bowl 1, cucumber 1, cutting board 3, feta cheese 1, greek salad 1, knife 1, olive oil 2, onion 1, oregano 1, red wine vinegar 2, salad tongs 1, tomato 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 08-greek_salad.foon:3, and no unit puts one back
(define (domain foon-relational-61817839)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    black_olive - physical-object
    bottle - physical-object
    bowl - physical-object
    cucumber - physical-object
    cutting_board - physical-object
    feta_cheese - physical-object
    greek_salad - physical-object
    knife - physical-object
    olive_oil - physical-object
    onion - physical-object
    oregano - physical-object
    red_wine_vinegar - physical-object
    salad_tongs - physical-object
    tomato - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    black_olive_in_bowl_pitted - object-state
    black_olive_pitted - object-state
    bottle_contains_olive_oil_red_wine_vinegar - object-state
    bowl_contains_avocado_lime_juice - object-state
    bowl_contains_avocado_lime_juice_onion - object-state
    bowl_contains_avocado_lime_juice_onion_tomato - object-state
    bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6 - object-state
    bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4 - object-state
    bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato - object-state
    bowl_contains_black_olive_cucumber_onion_tomato - object-state
    bowl_contains_cucumber - object-state
    bowl_contains_cucumber_onion_tomato - object-state
    bowl_contains_cucumber_tomato - object-state
    bowl_contains_greek_salad - object-state
    bowl_empty - object-state
    cucumber_in_bowl_sliced - object-state
    cucumber_on_cutting_board_sliced - object-state
    cucumber_on_cutting_board_whole - object-state
    cucumber_whole - object-state
    cutting_board_contains_cucumber - object-state
    cutting_board_contains_onion - object-state
    cutting_board_contains_tomato - object-state
    cutting_board_empty - object-state
    feta_cheese_crumbled - object-state
    feta_cheese_crumbled_in_bowl - object-state
    greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915 - object-state
    knife_plain - object-state
    olive_oil_in_bottle - object-state
    olive_oil_in_bowl - object-state
    onion_chopped_in_bowl - object-state
    onion_chopped_on_cutting_board - object-state
    onion_in_bowl_sliced - object-state
    onion_on_cutting_board_peeled - object-state
    onion_on_cutting_board_sliced - object-state
    onion_on_cutting_board_whole - object-state
    onion_whole - object-state
    oregano_dried - object-state
    oregano_in_bowl - object-state
    red_wine_vinegar_in_bottle - object-state
    red_wine_vinegar_in_bowl - object-state
    salad_tongs_plain - object-state
    tomato_chopped_in_bowl - object-state
    tomato_chopped_on_cutting_board - object-state
    tomato_on_cutting_board_whole - object-state
    tomato_whole - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
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

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters (?bowl - bowl ?onion - onion)
    :precondition (and
      (is ?bowl bowl_contains_avocado_lime_juice)
      (is ?onion onion_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_in_bowl)
      (in ?bowl ?onion)
      (not (is ?bowl bowl_contains_avocado_lime_juice))
      (not (is ?onion onion_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?onion) (not (on ?from_1 ?onion))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?onion) (is ?from_1 cutting_board_contains_onion)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_onion)))))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - bowl ?tomato - tomato)
    :precondition (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?tomato tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (occupied bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion))
      (not (is ?tomato tomato_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?tomato) (not (on ?from_1 ?tomato))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?tomato) (is ?from_1 cutting_board_contains_tomato)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_tomato)))))
    )
  )

  (:action pick-and-place_u78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?cucumber - cucumber)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?cucumber cucumber_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_cucumber)
      (is ?cucumber cucumber_on_cutting_board_whole)
      (on ?cutting_board ?cucumber)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?cucumber cucumber_whole))
    )
  )

  (:action slice_u79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters (?cutting_board - cutting_board ?cucumber - cucumber)
    :precondition (and
      (is ?cutting_board cutting_board_contains_cucumber)
      (is ?cucumber cucumber_on_cutting_board_whole)
      (on ?cutting_board ?cucumber)
      (occupied knife_plain)
    )
    :effect (and
      (is ?cucumber cucumber_on_cutting_board_sliced)
      (not (is ?cucumber cucumber_on_cutting_board_whole))
    )
  )

  (:action slice_u80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (on ?cutting_board ?onion)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_on_cutting_board_sliced)
      (not (is ?onion onion_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters (?bowl - bowl ?cucumber - cucumber)
    :precondition (and
      (is ?bowl bowl_empty)
      (is ?cucumber cucumber_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber)
      (is ?cucumber cucumber_in_bowl_sliced)
      (in ?bowl ?cucumber)
      (not (is ?bowl bowl_empty))
      (not (is ?cucumber cucumber_on_cutting_board_sliced))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?cucumber) (not (on ?from_1 ?cucumber))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?cucumber) (is ?from_1 cutting_board_contains_cucumber)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_cucumber)))))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - bowl ?tomato - tomato)
    :precondition (and
      (is ?bowl bowl_contains_cucumber)
      (is ?tomato tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (not (is ?bowl bowl_contains_cucumber))
      (not (is ?tomato tomato_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?tomato) (not (on ?from_1 ?tomato))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?tomato) (is ?from_1 cutting_board_contains_tomato)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_tomato)))))
    )
  )

  (:action pick-and-place_u83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters (?bowl - bowl ?onion - onion)
    :precondition (and
      (is ?bowl bowl_contains_cucumber_tomato)
      (is ?onion onion_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_onion_tomato)
      (is ?onion onion_in_bowl_sliced)
      (in ?bowl ?onion)
      (not (is ?bowl bowl_contains_cucumber_tomato))
      (not (is ?onion onion_on_cutting_board_sliced))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?onion) (not (on ?from_1 ?onion))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?onion) (is ?from_1 cutting_board_contains_onion)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_onion)))))
    )
  )

  (:action pick-and-place_u84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters (?bowl - bowl ?black_olive - black_olive)
    :precondition (and
      (is ?bowl bowl_contains_cucumber_onion_tomato)
      (is ?black_olive black_olive_pitted)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato)
      (is ?black_olive black_olive_in_bowl_pitted)
      (in ?bowl ?black_olive)
      (not (is ?bowl bowl_contains_cucumber_onion_tomato))
      (not (is ?black_olive black_olive_pitted))
    )
  )

  (:action sprinkle_u85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters (?bowl - bowl ?feta_cheese - feta_cheese)
    :precondition (and
      (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato)
      (is ?feta_cheese feta_cheese_crumbled)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is ?feta_cheese feta_cheese_crumbled_in_bowl)
      (in ?bowl ?feta_cheese)
      (not (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato))
      (not (is ?feta_cheese feta_cheese_crumbled))
    )
  )

  (:action pour_u86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters (?bowl - bowl ?olive_oil_portion - olive_oil ?red_wine_vinegar_portion - red_wine_vinegar)
    :precondition (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is ?olive_oil_portion not-yet-made)
      (occupied olive_oil_in_bottle)
      (is ?red_wine_vinegar_portion not-yet-made)
      (occupied red_wine_vinegar_in_bottle)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is ?olive_oil_portion olive_oil_in_bowl)
      (in ?bowl ?olive_oil_portion)
      (is ?red_wine_vinegar_portion red_wine_vinegar_in_bowl)
      (in ?bowl ?red_wine_vinegar_portion)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato))
      (not (is ?olive_oil_portion not-yet-made))
      (not (is ?red_wine_vinegar_portion not-yet-made))
    )
  )

  (:action sprinkle_u87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters (?bowl - bowl ?oregano - oregano)
    :precondition (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is ?oregano oregano_dried)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is ?oregano oregano_in_bowl)
      (in ?bowl ?oregano)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4))
      (not (is ?oregano oregano_dried))
    )
  )

  (:action toss_u88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters (?bowl - bowl ?cucumber - cucumber ?tomato - tomato ?onion - onion ?black_olive - black_olive ?feta_cheese - feta_cheese ?olive_oil - olive_oil ?red_wine_vinegar - red_wine_vinegar ?oregano - oregano ?greek_salad - greek_salad)
    :precondition (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is ?cucumber cucumber_in_bowl_sliced)
      (in ?bowl ?cucumber)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (is ?onion onion_in_bowl_sliced)
      (in ?bowl ?onion)
      (is ?black_olive black_olive_in_bowl_pitted)
      (in ?bowl ?black_olive)
      (is ?feta_cheese feta_cheese_crumbled_in_bowl)
      (in ?bowl ?feta_cheese)
      (is ?olive_oil olive_oil_in_bowl)
      (in ?bowl ?olive_oil)
      (is ?red_wine_vinegar red_wine_vinegar_in_bowl)
      (in ?bowl ?red_wine_vinegar)
      (is ?oregano oregano_in_bowl)
      (in ?bowl ?oregano)
      (occupied salad_tongs_plain)
      (is ?greek_salad not-yet-made)
    )
    :effect (and
      (is ?bowl bowl_contains_greek_salad)
      (occupied bowl_contains_greek_salad)
      (is ?cucumber consumed)
      (is ?tomato consumed)
      (is ?onion consumed)
      (is ?black_olive consumed)
      (is ?feta_cheese consumed)
      (is ?olive_oil consumed)
      (is ?red_wine_vinegar consumed)
      (is ?oregano consumed)
      (is ?greek_salad greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (occupied greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (in ?bowl ?greek_salad)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6))
      (not (is ?cucumber cucumber_in_bowl_sliced))
      (not (in ?bowl ?cucumber))
      (not (is ?tomato tomato_chopped_in_bowl))
      (not (in ?bowl ?tomato))
      (not (is ?onion onion_in_bowl_sliced))
      (not (in ?bowl ?onion))
      (not (is ?black_olive black_olive_in_bowl_pitted))
      (not (in ?bowl ?black_olive))
      (not (is ?feta_cheese feta_cheese_crumbled_in_bowl))
      (not (in ?bowl ?feta_cheese))
      (not (is ?olive_oil olive_oil_in_bowl))
      (not (in ?bowl ?olive_oil))
      (not (is ?red_wine_vinegar red_wine_vinegar_in_bowl))
      (not (in ?bowl ?red_wine_vinegar))
      (not (is ?oregano oregano_in_bowl))
      (not (in ?bowl ?oregano))
      (not (is ?greek_salad not-yet-made))
      (forall (?cucumber_alike - cucumber) (when (and (in ?bowl ?cucumber_alike) (is ?cucumber_alike cucumber_in_bowl_sliced)) (and (is ?cucumber_alike consumed) (not (in ?bowl ?cucumber_alike)) (not (is ?cucumber_alike cucumber_in_bowl_sliced)))))
      (forall (?tomato_alike - tomato) (when (and (in ?bowl ?tomato_alike) (is ?tomato_alike tomato_chopped_in_bowl)) (and (is ?tomato_alike consumed) (not (in ?bowl ?tomato_alike)) (not (is ?tomato_alike tomato_chopped_in_bowl)))))
      (forall (?onion_alike - onion) (when (and (in ?bowl ?onion_alike) (is ?onion_alike onion_chopped_in_bowl)) (and (is ?onion_alike consumed) (not (in ?bowl ?onion_alike)) (not (is ?onion_alike onion_chopped_in_bowl)))))
      (forall (?onion_alike-2 - onion) (when (and (in ?bowl ?onion_alike-2) (is ?onion_alike-2 onion_in_bowl_sliced)) (and (is ?onion_alike-2 consumed) (not (in ?bowl ?onion_alike-2)) (not (is ?onion_alike-2 onion_in_bowl_sliced)))))
      (forall (?black_olive_alike - black_olive) (when (and (in ?bowl ?black_olive_alike) (is ?black_olive_alike black_olive_in_bowl_pitted)) (and (is ?black_olive_alike consumed) (not (in ?bowl ?black_olive_alike)) (not (is ?black_olive_alike black_olive_in_bowl_pitted)))))
      (forall (?feta_cheese_alike - feta_cheese) (when (and (in ?bowl ?feta_cheese_alike) (is ?feta_cheese_alike feta_cheese_crumbled_in_bowl)) (and (is ?feta_cheese_alike consumed) (not (in ?bowl ?feta_cheese_alike)) (not (is ?feta_cheese_alike feta_cheese_crumbled_in_bowl)))))
      (forall (?olive_oil_alike - olive_oil) (when (and (in ?bowl ?olive_oil_alike) (is ?olive_oil_alike olive_oil_in_bowl)) (and (is ?olive_oil_alike consumed) (not (in ?bowl ?olive_oil_alike)) (not (is ?olive_oil_alike olive_oil_in_bowl)))))
      (forall (?red_wine_vinegar_alike - red_wine_vinegar) (when (and (in ?bowl ?red_wine_vinegar_alike) (is ?red_wine_vinegar_alike red_wine_vinegar_in_bowl)) (and (is ?red_wine_vinegar_alike consumed) (not (in ?bowl ?red_wine_vinegar_alike)) (not (is ?red_wine_vinegar_alike red_wine_vinegar_in_bowl)))))
      (forall (?oregano_alike - oregano) (when (and (in ?bowl ?oregano_alike) (is ?oregano_alike oregano_in_bowl)) (and (is ?oregano_alike consumed) (not (in ?bowl ?oregano_alike)) (not (is ?oregano_alike oregano_in_bowl)))))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: greek salad (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}, in [bowl])
    :parameters ()
    :precondition (and
      (occupied greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
    )
    :effect (and
      (goal-reached)
    )
  )
)
