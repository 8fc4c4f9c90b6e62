; foon2pddl, encoding instances, level 3: 18 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 15 (black olive 1, bowl 1, cucumber 1, cutting board 3, feta cheese 1, greek salad 1, knife 1, olive oil 1, onion 1, oregano 1, red wine vinegar 1, salad tongs 1, tomato 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 08-greek_salad.foon:3, and no unit puts one back
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-c6402eed)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    black_olive_in_bowl_pitted - object-state
    black_olive_pitted - object-state
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
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_black_olive ?x - physical-object)  ; ?x is of type black_olive
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_cucumber ?x - physical-object)  ; ?x is of type cucumber
    (type_cutting_board ?x - physical-object)  ; ?x is of type cutting_board
    (type_feta_cheese ?x - physical-object)  ; ?x is of type feta_cheese
    (type_greek_salad ?x - physical-object)  ; ?x is of type greek_salad
    (type_knife ?x - physical-object)  ; ?x is of type knife
    (type_olive_oil ?x - physical-object)  ; ?x is of type olive_oil
    (type_onion ?x - physical-object)  ; ?x is of type onion
    (type_oregano ?x - physical-object)  ; ?x is of type oregano
    (type_red_wine_vinegar ?x - physical-object)  ; ?x is of type red_wine_vinegar
    (type_salad_tongs ?x - physical-object)  ; ?x is of type salad_tongs
    (type_tomato ?x - physical-object)  ; ?x is of type tomato
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?onion - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_onion ?onion)
      (together ?cutting_board ?onion)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_onion)
      (is ?onion onion_whole)
      (lane ?onion onion_whole onion_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?onion onion_whole))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (lane ?onion onion_on_cutting_board_whole onion_on_cutting_board_peeled)
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
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (lane ?onion onion_on_cutting_board_peeled onion_chopped_on_cutting_board)
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
    :parameters (?cutting_board - physical-object ?tomato - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_tomato ?tomato)
      (together ?cutting_board ?tomato)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_tomato)
      (is ?tomato tomato_whole)
      (lane ?tomato tomato_whole tomato_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_tomato)
      (occupied cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?tomato tomato_whole))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters (?tomato - physical-object)
    :precondition (and
      (type_tomato ?tomato)
      (occupied cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (lane ?tomato tomato_on_cutting_board_whole tomato_chopped_on_cutting_board)
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
    :parameters (?bowl - physical-object ?onion - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_onion ?onion)
      (together ?bowl ?onion)
      (is ?bowl bowl_contains_avocado_lime_juice)
      (lane ?bowl bowl_contains_avocado_lime_juice bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_on_cutting_board)
      (lane ?onion onion_chopped_on_cutting_board onion_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_in_bowl)
      (occupied onion_chopped_in_bowl)
      (not (is ?bowl bowl_contains_avocado_lime_juice))
      (not (is ?onion onion_chopped_on_cutting_board))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - physical-object ?tomato - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_tomato ?tomato)
      (together ?bowl ?tomato)
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (lane ?bowl bowl_contains_avocado_lime_juice_onion bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_on_cutting_board)
      (lane ?tomato tomato_chopped_on_cutting_board tomato_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (occupied bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (occupied tomato_chopped_in_bowl)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion))
      (not (is ?tomato tomato_chopped_on_cutting_board))
    )
  )

  (:action pick-and-place_u78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters (?cutting_board - physical-object ?cucumber - physical-object)
    :precondition (and
      (type_cutting_board ?cutting_board)
      (type_cucumber ?cucumber)
      (together ?cutting_board ?cucumber)
      (is ?cutting_board cutting_board_empty)
      (lane ?cutting_board cutting_board_empty cutting_board_contains_cucumber)
      (is ?cucumber cucumber_whole)
      (lane ?cucumber cucumber_whole cucumber_on_cutting_board_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_cucumber)
      (occupied cutting_board_contains_cucumber)
      (is ?cucumber cucumber_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?cucumber cucumber_whole))
    )
  )

  (:action slice_u79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters (?cucumber - physical-object)
    :precondition (and
      (type_cucumber ?cucumber)
      (occupied cutting_board_contains_cucumber)
      (is ?cucumber cucumber_on_cutting_board_whole)
      (lane ?cucumber cucumber_on_cutting_board_whole cucumber_on_cutting_board_sliced)
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
    :parameters (?onion - physical-object)
    :precondition (and
      (type_onion ?onion)
      (occupied cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (lane ?onion onion_on_cutting_board_peeled onion_on_cutting_board_sliced)
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
    :parameters (?bowl - physical-object ?cucumber - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_cucumber ?cucumber)
      (together ?bowl ?cucumber)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_cucumber)
      (is ?cucumber cucumber_on_cutting_board_sliced)
      (lane ?cucumber cucumber_on_cutting_board_sliced cucumber_in_bowl_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber)
      (is ?cucumber cucumber_in_bowl_sliced)
      (occupied cucumber_in_bowl_sliced)
      (not (is ?bowl bowl_empty))
      (not (is ?cucumber cucumber_on_cutting_board_sliced))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - physical-object ?tomato - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_tomato ?tomato)
      (together ?bowl ?tomato)
      (is ?bowl bowl_contains_cucumber)
      (lane ?bowl bowl_contains_cucumber bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_on_cutting_board)
      (lane ?tomato tomato_chopped_on_cutting_board tomato_chopped_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (occupied tomato_chopped_in_bowl)
      (not (is ?bowl bowl_contains_cucumber))
      (not (is ?tomato tomato_chopped_on_cutting_board))
    )
  )

  (:action pick-and-place_u83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters (?bowl - physical-object ?onion - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_onion ?onion)
      (together ?bowl ?onion)
      (is ?bowl bowl_contains_cucumber_tomato)
      (lane ?bowl bowl_contains_cucumber_tomato bowl_contains_cucumber_onion_tomato)
      (is ?onion onion_on_cutting_board_sliced)
      (lane ?onion onion_on_cutting_board_sliced onion_in_bowl_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_onion_tomato)
      (is ?onion onion_in_bowl_sliced)
      (occupied onion_in_bowl_sliced)
      (not (is ?bowl bowl_contains_cucumber_tomato))
      (not (is ?onion onion_on_cutting_board_sliced))
    )
  )

  (:action pick-and-place_u84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters (?bowl - physical-object ?black_olive - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_black_olive ?black_olive)
      (together ?bowl ?black_olive)
      (is ?bowl bowl_contains_cucumber_onion_tomato)
      (lane ?bowl bowl_contains_cucumber_onion_tomato bowl_contains_black_olive_cucumber_onion_tomato)
      (is ?black_olive black_olive_pitted)
      (lane ?black_olive black_olive_pitted black_olive_in_bowl_pitted)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato)
      (is ?black_olive black_olive_in_bowl_pitted)
      (occupied black_olive_in_bowl_pitted)
      (not (is ?bowl bowl_contains_cucumber_onion_tomato))
      (not (is ?black_olive black_olive_pitted))
    )
  )

  (:action sprinkle_u85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters (?bowl - physical-object ?feta_cheese - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_feta_cheese ?feta_cheese)
      (together ?bowl ?feta_cheese)
      (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato)
      (lane ?bowl bowl_contains_black_olive_cucumber_onion_tomato bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is ?feta_cheese feta_cheese_crumbled)
      (lane ?feta_cheese feta_cheese_crumbled feta_cheese_crumbled_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is ?feta_cheese feta_cheese_crumbled_in_bowl)
      (occupied feta_cheese_crumbled_in_bowl)
      (not (is ?bowl bowl_contains_black_olive_cucumber_onion_tomato))
      (not (is ?feta_cheese feta_cheese_crumbled))
    )
  )

  (:action pour_u86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters (?bowl - physical-object ?olive_oil - physical-object ?red_wine_vinegar - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_olive_oil ?olive_oil)
      (type_red_wine_vinegar ?red_wine_vinegar)
      (together ?bowl ?olive_oil)
      (together ?olive_oil ?red_wine_vinegar)
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (lane ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is ?olive_oil olive_oil_in_bottle)
      (lane ?olive_oil olive_oil_in_bottle olive_oil_in_bowl)
      (is ?red_wine_vinegar red_wine_vinegar_in_bottle)
      (lane ?red_wine_vinegar red_wine_vinegar_in_bottle red_wine_vinegar_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is ?olive_oil olive_oil_in_bowl)
      (occupied olive_oil_in_bowl)
      (is ?red_wine_vinegar red_wine_vinegar_in_bowl)
      (occupied red_wine_vinegar_in_bowl)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato))
      (not (is ?olive_oil olive_oil_in_bottle))
      (not (is ?red_wine_vinegar red_wine_vinegar_in_bottle))
    )
  )

  (:action sprinkle_u87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters (?bowl - physical-object ?oregano - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_oregano ?oregano)
      (together ?bowl ?oregano)
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (lane ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4 bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is ?oregano oregano_dried)
      (lane ?oregano oregano_dried oregano_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is ?oregano oregano_in_bowl)
      (occupied oregano_in_bowl)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4))
      (not (is ?oregano oregano_dried))
    )
  )

  (:action toss_u88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters (?bowl - physical-object ?greek_salad - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_greek_salad ?greek_salad)
      (together ?bowl ?greek_salad)
      (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (lane ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6 bowl_contains_greek_salad)
      (occupied cucumber_in_bowl_sliced)
      (occupied tomato_chopped_in_bowl)
      (occupied onion_in_bowl_sliced)
      (occupied black_olive_in_bowl_pitted)
      (occupied feta_cheese_crumbled_in_bowl)
      (occupied olive_oil_in_bowl)
      (occupied red_wine_vinegar_in_bowl)
      (occupied oregano_in_bowl)
      (occupied salad_tongs_plain)
      (is ?greek_salad not-yet-made)
      (lane ?greek_salad not-yet-made greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
    )
    :effect (and
      (is ?bowl bowl_contains_greek_salad)
      (occupied bowl_contains_greek_salad)
      (is ?greek_salad greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (occupied greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (not (is ?bowl bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6))
      (not (is ?greek_salad not-yet-made))
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
