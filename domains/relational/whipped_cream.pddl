; foon2pddl, encoding relational, level 3: 4 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 8 (bowl 1, heavy cream 2, mixing bowl 1, spatula 1, sugar 1, whipped cream 1, whisk 1)
(define (domain foon-relational-733e9be4)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    bowl - physical-object
    carton - physical-object
    heavy_cream - physical-object
    mixing_bowl - physical-object
    spatula - physical-object
    sugar - physical-object
    whipped_cream - physical-object
    whisk - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    bowl_contains_whipped_cream - object-state
    bowl_empty - object-state
    carton_contains_heavy_cream - object-state
    heavy_cream_in_carton - object-state
    heavy_cream_in_mixing_bowl - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_whipped_cream - object-state
    mixing_bowl_empty - object-state
    spatula_plain - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whipped_cream_in_bowl_whipped - object-state
    whipped_cream_in_mixing_bowl_whipped - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?heavy_cream_portion - heavy_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?heavy_cream_portion not-yet-made)
      (occupied heavy_cream_in_carton)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream_portion heavy_cream_in_mixing_bowl)
      (in ?mixing_bowl ?heavy_cream_portion)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?heavy_cream_portion not-yet-made))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?sugar - sugar)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?sugar sugar_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
  )

  (:action scoop_u16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters (?mixing_bowl - mixing_bowl ?whipped_cream - whipped_cream ?bowl - bowl)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (in ?mixing_bowl ?whipped_cream)
      (occupied spatula_plain)
      (is ?bowl bowl_empty)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?whipped_cream whipped_cream_in_bowl_whipped)
      (occupied whipped_cream_in_bowl_whipped)
      (in ?bowl ?whipped_cream)
      (is ?bowl bowl_contains_whipped_cream)
      (occupied bowl_contains_whipped_cream)
      (not (is ?mixing_bowl mixing_bowl_contains_whipped_cream))
      (not (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped))
      (not (in ?mixing_bowl ?whipped_cream))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters (?mixing_bowl - mixing_bowl ?heavy_cream - heavy_cream ?sugar - sugar ?whipped_cream - whipped_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?heavy_cream heavy_cream_in_mixing_bowl)
      (in ?mixing_bowl ?heavy_cream)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (occupied whisk_plain)
      (is ?whipped_cream not-yet-made)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (is ?heavy_cream consumed)
      (is ?sugar consumed)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (in ?mixing_bowl ?whipped_cream)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?heavy_cream heavy_cream_in_mixing_bowl))
      (not (in ?mixing_bowl ?heavy_cream))
      (not (is ?sugar sugar_in_mixing_bowl))
      (not (in ?mixing_bowl ?sugar))
      (not (is ?whipped_cream not-yet-made))
      (forall (?heavy_cream_alike - heavy_cream) (when (and (in ?mixing_bowl ?heavy_cream_alike) (is ?heavy_cream_alike heavy_cream_in_mixing_bowl)) (and (is ?heavy_cream_alike consumed) (not (in ?mixing_bowl ?heavy_cream_alike)) (not (is ?heavy_cream_alike heavy_cream_in_mixing_bowl)))))
      (forall (?sugar_alike - sugar) (when (and (in ?mixing_bowl ?sugar_alike) (is ?sugar_alike sugar_in_mixing_bowl)) (and (is ?sugar_alike consumed) (not (in ?mixing_bowl ?sugar_alike)) (not (is ?sugar_alike sugar_in_mixing_bowl)))))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: whipped cream (in [bowl], whipped)
    :parameters ()
    :precondition (and
      (occupied whipped_cream_in_bowl_whipped)
    )
    :effect (and
      (goal-reached)
    )
  )
)
